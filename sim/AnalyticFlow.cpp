#include "sim/AnalyticFlow.h"

#include <muParser.h>

#include <numbers>
#include <stdexcept>

namespace vf::sim {

namespace {

// muparser binds variables by address, so each parser owns the x, y, t it reads.
struct BoundParser {
    double x = 0.0, y = 0.0, t = 0.0;
    mu::Parser parser;

    explicit BoundParser(const std::string& expression)
    {
        parser.DefineVar("x", &x);
        parser.DefineVar("y", &y);
        parser.DefineVar("t", &t);
        parser.DefineConst("pi", std::numbers::pi);
        parser.SetExpr(expression);
        parser.Eval();  // muparser compiles lazily: surface syntax errors now, not mid-run
    }
    BoundParser(const BoundParser&) = delete;
    BoundParser& operator=(const BoundParser&) = delete;

    double operator()(Vec2 p, double time)
    {
        x = p.x;
        y = p.y;
        t = time;
        return parser.Eval();
    }
};

std::string describe(const mu::Parser::exception_type& e)
{
    return "expression \"" + e.GetExpr() + "\": " + e.GetMsg();
}

} // namespace

struct AnalyticFlow::Parsers {
    BoundParser u, v;
    Parsers(const std::string& uExpr, const std::string& vExpr) : u(uExpr), v(vExpr) {}
};

AnalyticFlow::AnalyticFlow(const std::string& u, const std::string& v)
{
    try {
        m_parsers = std::make_unique<Parsers>(u, v);
    } catch (const mu::Parser::exception_type& e) {
        throw std::invalid_argument(describe(e));
    }
}

AnalyticFlow::~AnalyticFlow() = default;

std::string AnalyticFlow::check(const std::string& expression)
{
    try {
        BoundParser probe(expression);
        return {};
    } catch (const mu::Parser::exception_type& e) {
        return describe(e);
    }
}

Vec2 AnalyticFlow::velocity(Vec2 p, double t) const
{
    return {m_parsers->u(p, t), m_parsers->v(p, t)};
}

double AnalyticFlow::vorticity(Vec2 p, double t) const
{
    // Central differences; h is far below any feature an expression-defined flow has on the canvas.
    constexpr double h = 1e-5;
    const double dvdx = (m_parsers->v(p + Vec2(h, 0), t) - m_parsers->v(p - Vec2(h, 0), t)) / (2 * h);
    const double dudy = (m_parsers->u(p + Vec2(0, h), t) - m_parsers->u(p - Vec2(0, h), t)) / (2 * h);
    return dvdx - dudy;
}

} // namespace vf::sim
