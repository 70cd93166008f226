#include "sim/AnalyticFlow.h"

#include <muParser.h>

#include <numbers>
#include <stdexcept>
#include <string>

namespace vf::sim {

namespace {

// Expressions are short formulas. muparser's compile time grows with the square of the length
// (a sum of 8,000 terms took seconds), and the OpenCL backend's translator recurses per
// parenthesis, so longer text is refused before either sees it.
constexpr std::size_t kMaxExpressionLength = 1000;

// `expression "…"` for a message, cut short with the length where the text is long.
std::string quoted(const std::string& expression)
{
    constexpr std::size_t kMaxShown = 40;
    if (expression.size() <= kMaxShown)
        return "expression \"" + expression + "\"";
    return "expression \"" + expression.substr(0, kMaxShown) + "...\" (" + std::to_string(expression.size()) + " characters)";
}

// muparser binds variables by address, so each parser owns the x, y, t it reads. A bad expression
// throws std::invalid_argument with its message.
struct BoundParser {
    double x = 0.0, y = 0.0, t = 0.0;
    mu::Parser parser;

    explicit BoundParser(const std::string& expression)
    {
        parser.DefineVar("x", &x);
        parser.DefineVar("y", &y);
        parser.DefineVar("t", &t);
        parser.DefineConst("pi", std::numbers::pi);
        if (expression.size() > kMaxExpressionLength)
            throw std::invalid_argument(quoted(expression) + ": longer than the " + std::to_string(kMaxExpressionLength) +
                                        " characters an expression may have");
        try {
            parser.SetExpr(expression);
            parser.Eval();  // muparser compiles lazily: surface syntax errors now, not mid-run
        } catch (const mu::Parser::exception_type& e) {
            throw std::invalid_argument(quoted(expression) + ": " + e.GetMsg());
        }
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

} // namespace

struct AnalyticFlow::Parsers {
    BoundParser u, v;
    Parsers(const std::string& uExpr, const std::string& vExpr) : u(uExpr), v(vExpr) {}
};

AnalyticFlow::AnalyticFlow(const std::string& u, const std::string& v) : m_parsers(std::make_unique<Parsers>(u, v)) {}

AnalyticFlow::~AnalyticFlow() = default;

std::string AnalyticFlow::check(const std::string& expression)
{
    try {
        BoundParser probe(expression);
        return {};
    } catch (const std::invalid_argument& e) {
        return e.what();
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
