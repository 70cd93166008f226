#pragma once
// Analytic flows on the device: the scene's muparser expressions in x, y, t, translated to
// OpenCL C that defines flowVelocity/flowVorticity (see FlowBinding.h).
//
// The translator accepts the documented expression language (docs/scene-format.md): numbers,
// x, y, t, pi, + - * / ^ with muparser's precedence (unary minus binds looser than ^, so
// -x^2 is -(x^2); ^ is right-associative), parentheses, and the functions sin, cos, tan, exp,
// sqrt, abs. Anything else muparser would take is refused with a message naming it, and the
// caller falls back to the reference backend.
#include <memory>
#include <stdexcept>
#include <string>

namespace vf::sim::opencl {

class UnsupportedExpression : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A parsed expression, evaluable on the host (for tests against muparser) and printable as C.
class Expression {
public:
    static Expression parse(const std::string& text);  // throws UnsupportedExpression
    Expression(Expression&&) noexcept;
    Expression& operator=(Expression&&) noexcept;
    ~Expression();

    double evaluate(double x, double y, double t) const;
    std::string toOpenCl() const;  // a float expression in x, y, t

    struct Node;

private:
    explicit Expression(std::unique_ptr<Node> root);
    std::unique_ptr<Node> m_root;
};

// The OpenCL C source defining flowVelocity and flowVorticity for u(x, y, t), v(x, y, t).
std::string analyticFlowSource(const std::string& u, const std::string& v);

} // namespace vf::sim::opencl
