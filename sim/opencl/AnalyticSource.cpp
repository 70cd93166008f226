#include "sim/opencl/AnalyticSource.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace vf::sim::opencl {

struct Expression::Node {
    enum class Kind { Number, Variable, Negate, Add, Subtract, Multiply, Divide, Power, Function };
    Kind kind;
    double value = 0.0;  // Number
    char variable = 0;   // Variable: 'x', 'y', 't'
    std::string function;
    std::unique_ptr<Node> a, b;
};

namespace {

using Node = Expression::Node;
using Kind = Node::Kind;

struct FunctionSpec {
    const char* name;
    const char* openCl;
    double (*evaluate)(double);
};

const FunctionSpec functions[] = {
    {"sin", "sin", [](double v) { return std::sin(v); }},   {"cos", "cos", [](double v) { return std::cos(v); }},
    {"tan", "tan", [](double v) { return std::tan(v); }},   {"exp", "exp", [](double v) { return std::exp(v); }},
    {"sqrt", "sqrt", [](double v) { return std::sqrt(v); }}, {"abs", "fabs", [](double v) { return std::abs(v); }},
};

const FunctionSpec* findFunction(const std::string& name)
{
    for (const FunctionSpec& f : functions)
        if (name == f.name)
            return &f;
    return nullptr;
}

std::unique_ptr<Node> make(Kind kind, std::unique_ptr<Node> a = {}, std::unique_ptr<Node> b = {})
{
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->a = std::move(a);
    n->b = std::move(b);
    return n;
}

// Recursive descent over muparser's precedence: additive < multiplicative < unary sign < power.
class Parser {
public:
    explicit Parser(const std::string& text) : m_text(text) {}

    std::unique_ptr<Node> parseAll()
    {
        auto root = additive();
        skipSpace();
        if (m_at != m_text.size())
            fail("unexpected '" + std::string(1, m_text[m_at]) + "'");
        return root;
    }

private:
    [[noreturn]] void fail(const std::string& what) const
    {
        throw UnsupportedExpression("expression \"" + m_text + "\" at position " + std::to_string(m_at + 1) + ": " + what);
    }

    void skipSpace()
    {
        while (m_at < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_at])))
            ++m_at;
    }

    bool take(char c)
    {
        skipSpace();
        if (m_at < m_text.size() && m_text[m_at] == c) {
            ++m_at;
            return true;
        }
        return false;
    }

    std::unique_ptr<Node> additive()
    {
        auto left = multiplicative();
        for (;;) {
            if (take('+'))
                left = make(Kind::Add, std::move(left), multiplicative());
            else if (take('-'))
                left = make(Kind::Subtract, std::move(left), multiplicative());
            else
                return left;
        }
    }

    std::unique_ptr<Node> multiplicative()
    {
        auto left = sign();
        for (;;) {
            if (take('*'))
                left = make(Kind::Multiply, std::move(left), sign());
            else if (take('/'))
                left = make(Kind::Divide, std::move(left), sign());
            else
                return left;
        }
    }

    std::unique_ptr<Node> sign()
    {
        if (take('-'))
            return make(Kind::Negate, sign());
        if (take('+'))
            return sign();
        return power();
    }

    std::unique_ptr<Node> power()
    {
        auto base = primary();
        if (take('^'))
            return make(Kind::Power, std::move(base), sign());  // right-associative: a^b^c = a^(b^c)
        return base;
    }

    std::unique_ptr<Node> primary()
    {
        skipSpace();
        if (take('(')) {
            auto inner = additive();
            if (!take(')'))
                fail("missing ')'");
            return inner;
        }
        if (m_at < m_text.size() && (std::isdigit(static_cast<unsigned char>(m_text[m_at])) || m_text[m_at] == '.'))
            return number();
        const std::string name = identifier();
        if (name.empty())
            fail(m_at < m_text.size() ? "unexpected '" + std::string(1, m_text[m_at]) + "'" : "unexpected end");
        if (name == "x" || name == "y" || name == "t") {
            auto n = make(Kind::Variable);
            n->variable = name[0];
            return n;
        }
        if (name == "pi" || name == "_pi") {
            auto n = make(Kind::Number);
            n->value = std::numbers::pi;
            return n;
        }
        if (name == "_e") {
            auto n = make(Kind::Number);
            n->value = std::numbers::e;
            return n;
        }
        if (!findFunction(name))
            fail("'" + name + "' is not supported by the OpenCL backend (use sin, cos, tan, exp, sqrt, abs)");
        if (!take('('))
            fail("'" + name + "' needs '('");
        auto n = make(Kind::Function, additive());
        n->function = name;
        if (!take(')'))
            fail("missing ')'");
        return n;
    }

    std::unique_ptr<Node> number()
    {
        double value = 0.0;
        const char* begin = m_text.data() + m_at;
        const auto [end, error] = std::from_chars(begin, m_text.data() + m_text.size(), value);
        if (error != std::errc())
            fail("bad number");
        m_at += std::size_t(end - begin);
        auto n = make(Kind::Number);
        n->value = value;
        return n;
    }

    std::string identifier()
    {
        const std::size_t start = m_at;
        while (m_at < m_text.size() && (std::isalnum(static_cast<unsigned char>(m_text[m_at])) || m_text[m_at] == '_'))
            ++m_at;
        return m_text.substr(start, m_at - start);
    }

    const std::string& m_text;
    std::size_t m_at = 0;
};

double evaluate(const Node& n, double x, double y, double t)
{
    switch (n.kind) {
    case Kind::Number: return n.value;
    case Kind::Variable: return n.variable == 'x' ? x : n.variable == 'y' ? y : t;
    case Kind::Negate: return -evaluate(*n.a, x, y, t);
    case Kind::Add: return evaluate(*n.a, x, y, t) + evaluate(*n.b, x, y, t);
    case Kind::Subtract: return evaluate(*n.a, x, y, t) - evaluate(*n.b, x, y, t);
    case Kind::Multiply: return evaluate(*n.a, x, y, t) * evaluate(*n.b, x, y, t);
    case Kind::Divide: return evaluate(*n.a, x, y, t) / evaluate(*n.b, x, y, t);
    case Kind::Power: return std::pow(evaluate(*n.a, x, y, t), evaluate(*n.b, x, y, t));
    case Kind::Function: return findFunction(n.function)->evaluate(evaluate(*n.a, x, y, t));
    }
    return 0.0;
}

std::string floatLiteral(double value)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    const std::string digits = buffer;
    // "2f" is not a float literal in C; "2.0f" is.
    return digits + (digits.find_first_of(".e") == std::string::npos ? ".0f" : "f");
}

bool isSmallInteger(const Node& n)
{
    return n.kind == Kind::Number && n.value == std::floor(n.value) && std::abs(n.value) <= 64;
}

std::string toOpenCl(const Node& n)
{
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict, bug 105329) on long + chains.
    auto binary = [&n](const char* op) {
        std::string s = "(";
        s.append(toOpenCl(*n.a)).append(" ").append(op).append(" ").append(toOpenCl(*n.b)).append(")");
        return s;
    };
    switch (n.kind) {
    case Kind::Number: return floatLiteral(n.value);
    case Kind::Variable: return std::string(1, n.variable);
    case Kind::Negate: return "(-" + toOpenCl(*n.a) + ")";
    case Kind::Add: return binary("+");
    case Kind::Subtract: return binary("-");
    case Kind::Multiply: return binary("*");
    case Kind::Divide: return binary("/");
    case Kind::Power:
        // pown for whole exponents: exact for negative bases, as pow(x, 2.0) is on the host.
        if (isSmallInteger(*n.b))
            return "pown(" + toOpenCl(*n.a) + ", " + std::to_string(int(n.b->value)) + ")";
        return "pow(" + toOpenCl(*n.a) + ", " + toOpenCl(*n.b) + ")";
    case Kind::Function: return std::string(findFunction(n.function)->openCl) + "(" + toOpenCl(*n.a) + ")";
    }
    return {};
}

} // namespace

Expression::Expression(std::unique_ptr<Node> root) : m_root(std::move(root)) {}
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

Expression Expression::parse(const std::string& text)
{
    return Expression(Parser(text).parseAll());
}

double Expression::evaluate(double x, double y, double t) const
{
    return opencl::evaluate(*m_root, x, y, t);
}

std::string Expression::toOpenCl() const
{
    return opencl::toOpenCl(*m_root);
}

std::string analyticFlowSource(const std::string& u, const std::string& v)
{
    const std::string uC = Expression::parse(u).toOpenCl(), vC = Expression::parse(v).toOpenCl();
    // Vorticity by central differences. h is larger than on the host (1e-5) because float32
    // differences of nearby values lose digits fast; 1e-3 keeps about four good digits.
    return "inline __attribute__((always_inline)) float analyticU(float x, float y, float t) { return " + uC + "; }\n"
           "inline __attribute__((always_inline)) float analyticV(float x, float y, float t) { return " + vC + "; }\n"
           "inline __attribute__((always_inline)) float2 flowVelocity(FLOW_PARAMS, float2 p, float s)\n"
           "{ const float t = t0 + s * dt; return (float2)(analyticU(p.x, p.y, t), analyticV(p.x, p.y, t)); }\n"
           "inline __attribute__((always_inline)) float flowVorticity(FLOW_PARAMS, float2 p, float s)\n"
           "{\n"
           "    const float t = t0 + s * dt, h = 1e-3f;\n"
           "    return (analyticV(p.x + h, p.y, t) - analyticV(p.x - h, p.y, t)) / (2.0f * h)\n"
           "         - (analyticU(p.x, p.y + h, t) - analyticU(p.x, p.y - h, t)) / (2.0f * h);\n"
           "}\n"
           "VF_DEFINE_LANES_BY_LANE\n";
}

} // namespace vf::sim::opencl
