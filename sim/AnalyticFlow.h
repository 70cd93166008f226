#pragma once
// A prescribed velocity field u(x, y, t), v(x, y, t) given as muparser expressions.
#include "sim/Flow.h"

#include <memory>
#include <string>

namespace vf::sim {

class AnalyticFlow final : public Flow {
public:
    // Throws std::invalid_argument with a one-line message when an expression does not compile.
    AnalyticFlow(const std::string& u, const std::string& v);
    ~AnalyticFlow() override;

    // Empty when `expression` is a valid expression in x, y, t; otherwise what is wrong with it.
    static std::string check(const std::string& expression);

    void advance(double dt) override { m_time += dt; }
    double time() const override { return m_time; }
    void setTime(double t) override { m_time = t; }
    Vec2 velocity(Vec2 p, double t) const override;
    double vorticity(Vec2 p, double t) const override;

private:
    struct Parsers;
    std::unique_ptr<Parsers> m_parsers;
    double m_time = 0.0;
};

} // namespace vf::sim
