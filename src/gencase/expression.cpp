// SeaSpring — MIT licence.
/// \file expression.cpp
/// \brief Recursive-descent evaluator for GenCase-style expressions (see expression.h).
///
/// The text is evaluated while it is parsed. The branch that `eval(c,a,b)`, `&&` or `||`
/// does not take is still parsed and checked for syntax, unknown variables and functions
/// and argument counts, but value problems inside it (non-finite results, bad array
/// indices, roundpos without a grid) are not reported: `eval(n>0, 1/n, 0)` is fine for n=0.
#include "gencase/expression.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

namespace seaspring::gencase {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;

bool isIdentStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool isIdentifier(const std::string& s) {
    if (s.empty() || !isIdentStart(s[0])) return false;
    for (char c : s)
        if (!isIdentChar(c)) return false;
    return true;
}

std::string fmt(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    return buf;
}

/// A supported function. `max_args` < 0: no upper limit. `fn` is null for the ones the
/// parser evaluates itself (eval, roundpos*).
struct FunctionSpec {
    const char* name;
    int min_args;
    int max_args;
    double (*fn)(const std::vector<double>&);
};

double minOf(const std::vector<double>& a) { return *std::min_element(a.begin(), a.end()); }
double maxOf(const std::vector<double>& a) { return *std::max_element(a.begin(), a.end()); }
double fmodr(const std::vector<double>& a) { return a[0] - a[1] * std::floor(a[0] / a[1]); }

// clang-format off
const FunctionSpec kFunctions[] = {
    {"pi", 0, 0, [](const std::vector<double>&) { return kPi; }},
    {"e", 0, 0, [](const std::vector<double>&) { return 2.71828182845904523536; }},
    {"float", 1, 1, [](const std::vector<double>& a) { return a[0]; }},
    {"int", 1, 1, [](const std::vector<double>& a) { return std::trunc(a[0]); }},
    {"floor", 1, 1, [](const std::vector<double>& a) { return std::floor(a[0]); }},
    {"ceil", 1, 1, [](const std::vector<double>& a) { return std::ceil(a[0]); }},
    {"round", 1, 1, [](const std::vector<double>& a) { return std::round(a[0]); }},
    {"abs", 1, 1, [](const std::vector<double>& a) { return std::fabs(a[0]); }},
    {"fmod", 2, 2, [](const std::vector<double>& a) { return std::fmod(a[0], a[1]); }},
    {"fmodr", 2, 2, fmodr},
    {"sqrt", 1, 1, [](const std::vector<double>& a) { return std::sqrt(a[0]); }},
    {"exp", 1, 1, [](const std::vector<double>& a) { return std::exp(a[0]); }},
    {"log", 1, 1, [](const std::vector<double>& a) { return std::log(a[0]); }},
    {"log10", 1, 1, [](const std::vector<double>& a) { return std::log10(a[0]); }},
    {"pow", 2, 2, [](const std::vector<double>& a) { return std::pow(a[0], a[1]); }},
    {"sin", 1, 1, [](const std::vector<double>& a) { return std::sin(a[0]); }},
    {"cos", 1, 1, [](const std::vector<double>& a) { return std::cos(a[0]); }},
    {"tan", 1, 1, [](const std::vector<double>& a) { return std::tan(a[0]); }},
    {"sindg", 1, 1, [](const std::vector<double>& a) { return std::sin(a[0] * kDegToRad); }},
    {"cosdg", 1, 1, [](const std::vector<double>& a) { return std::cos(a[0] * kDegToRad); }},
    {"tandg", 1, 1, [](const std::vector<double>& a) { return std::tan(a[0] * kDegToRad); }},
    {"sinh", 1, 1, [](const std::vector<double>& a) { return std::sinh(a[0]); }},
    {"cosh", 1, 1, [](const std::vector<double>& a) { return std::cosh(a[0]); }},
    {"tanh", 1, 1, [](const std::vector<double>& a) { return std::tanh(a[0]); }},
    {"asin", 1, 1, [](const std::vector<double>& a) { return std::asin(a[0]); }},
    {"acos", 1, 1, [](const std::vector<double>& a) { return std::acos(a[0]); }},
    {"atan", 1, 1, [](const std::vector<double>& a) { return std::atan(a[0]); }},
    {"atan2", 2, 2, [](const std::vector<double>& a) { return std::atan2(a[0], a[1]); }},
    {"min", 2, -1, minOf},
    {"max", 2, -1, maxOf},
    {"eval", 3, 3, nullptr},
    {"roundpos", 3, 3, nullptr},
    {"roundposx", 1, 1, nullptr},
    {"roundposy", 1, 1, nullptr},
    {"roundposz", 1, 1, nullptr},
};
// clang-format on

/// GenCase functions that SeaSpring deliberately does not provide.
const char* const kUnsupportedFunctions[] = {"rand", "randint", "randinit", "wavelength"};

/// Parses and evaluates one expression text. `skip_` > 0 while inside a branch whose value
/// is not used (see the file comment).
/// The deepest nesting an expression may have (GenCase cases use fewer than 10 levels).
constexpr int kMaxExpressionDepth = 256;

class Parser {
public:
    Parser(const std::string& text, const ExpressionEvaluator& ev, Vec3d origin, double dp)
        : text_(text), ev_(ev), origin_(origin), dp_(dp) {}

    double run() {
        skipSpace();
        if (pos_ == text_.size()) fail(pos_, "empty expression");
        const double v = parseOr();
        skipSpace();
        if (pos_ != text_.size())
            fail(pos_, "unexpected " + describeHere() + " (expected an operator or the end)");
        return v;
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& what) const {
        throw ExpressionError("in '" + shown() + "' at position " + std::to_string(at) + ": " + what);
    }

    /// The text for messages: long texts are cut (a message must stay one readable line).
    std::string shown() const {
        if (text_.size() <= 80) return text_;
        return text_.substr(0, 60) + "... (" + std::to_string(text_.size()) + " characters)";
    }

    /// Non-finite results are errors, except in a branch that is not taken.
    double checked(double v, std::size_t at, const std::string& what) const {
        if (!std::isfinite(v) && skip_ == 0)
            throw ExpressionError("'" + shown() + "' gives a non-finite value: " + what +
                                  " at position " + std::to_string(at) + " gives " + fmt(v));
        return v;
    }

    /// The character at pos_, with a hint for the one-character forms of C operators.
    std::string describeHere() const {
        if (pos_ >= text_.size()) return "end of expression";
        const char c = text_[pos_];
        std::string d = "'" + std::string(1, c) + "'";
        if (c == '=') d += " (comparison is '==')";
        if (c == '&' || c == '|') d += std::string(" (use '") + c + c + "')";
        return d;
    }

    void skipSpace() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                       text_[pos_] == '\r' || text_[pos_] == '\n'))
            ++pos_;
    }

    /// Consumes `op` if it comes next (after whitespace).
    bool accept(const char* op) {
        skipSpace();
        const std::size_t n = std::strlen(op);
        if (text_.compare(pos_, n, op) != 0) return false;
        pos_ += n;
        return true;
    }

    void expect(char c) {
        skipSpace();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return;
        }
        fail(pos_, std::string("expected '") + c + "' but found " + describeHere());
    }

    double parseOr() {
        double v = parseAnd();
        while (accept("||")) {
            const bool decided = v != 0;
            skip_ += decided;
            const double r = parseAnd();
            skip_ -= decided;
            v = (decided || r != 0) ? 1.0 : 0.0;
        }
        return v;
    }

    double parseAnd() {
        double v = parseEquality();
        while (accept("&&")) {
            const bool decided = v == 0;
            skip_ += decided;
            const double r = parseEquality();
            skip_ -= decided;
            v = (!decided && r != 0) ? 1.0 : 0.0;
        }
        return v;
    }

    double parseEquality() {
        double v = parseRelational();
        for (;;) {
            if (accept("==")) v = (v == parseRelational()) ? 1.0 : 0.0;
            else if (accept("!=")) v = (v != parseRelational()) ? 1.0 : 0.0;
            else break;
        }
        return v;
    }

    double parseRelational() {
        double v = parseAdditive();
        for (;;) {
            if (accept("<=")) v = (v <= parseAdditive()) ? 1.0 : 0.0;
            else if (accept(">=")) v = (v >= parseAdditive()) ? 1.0 : 0.0;
            else if (accept("<")) v = (v < parseAdditive()) ? 1.0 : 0.0;
            else if (accept(">")) v = (v > parseAdditive()) ? 1.0 : 0.0;
            else break;
        }
        return v;
    }

    double parseAdditive() {
        double v = parseMultiplicative();
        for (;;) {
            skipSpace();
            const std::size_t at = pos_;
            if (accept("+")) v = checked(v + parseMultiplicative(), at, "'+'");
            else if (accept("-")) v = checked(v - parseMultiplicative(), at, "'-'");
            else break;
        }
        return v;
    }

    double parseMultiplicative() {
        double v = parseUnary();
        for (;;) {
            skipSpace();
            const std::size_t at = pos_;
            if (accept("*")) v = checked(v * parseUnary(), at, "'*'");
            else if (accept("/")) v = checked(v / parseUnary(), at, "'/'");
            else if (accept("%")) v = checked(std::fmod(v, parseUnary()), at, "'%'");
            else break;
        }
        return v;
    }

    /// Every nesting (parentheses, unary operators, '^', arguments, indices) passes through
    /// parseUnary; its depth is bounded so that no input can exhaust the stack.
    double parseUnary() {
        struct Depth {
            int& d;
            explicit Depth(int& v) : d(v) { ++d; }
            ~Depth() { --d; }
        } depth(depth_);
        if (depth_ > kMaxExpressionDepth)
            fail(pos_, "nested deeper than " + std::to_string(kMaxExpressionDepth) +
                           " levels (parentheses, unary operators, '^' or function calls)");
        if (accept("+")) return parseUnary();
        if (accept("-")) return -parseUnary();
        if (accept("!")) return parseUnary() == 0 ? 1.0 : 0.0;
        return parsePower();
    }

    /// primary ['^' unary]: right-associative, and -2^2 = -(2^2) since unary is above us.
    double parsePower() {
        const double base = parsePrimary();
        skipSpace();
        const std::size_t at = pos_;
        if (!accept("^")) return base;
        return checked(std::pow(base, parseUnary()), at, "'^'");
    }

    double parsePrimary() {
        skipSpace();
        const char c = pos_ < text_.size() ? text_[pos_] : '\0';
        if (isDigit(c) || c == '.') return parseNumber();
        if (c == '(') {
            ++pos_;
            const double v = parseOr();
            expect(')');
            return v;
        }
        if (isIdentStart(c)) return parseName();
        fail(pos_, "expected a number, variable, function or '(' but found " + describeHere());
    }

    /// C syntax: digits [. digits] [e[+-]digits], or . digits [...]; '1.' is allowed.
    double parseNumber() {
        const std::size_t start = pos_;
        std::size_t p = pos_;
        std::size_t digits = 0;
        while (p < text_.size() && isDigit(text_[p])) ++p, ++digits;
        if (p < text_.size() && text_[p] == '.') {
            ++p;
            while (p < text_.size() && isDigit(text_[p])) ++p, ++digits;
        }
        if (digits == 0) fail(start, "expected digits in a number");
        if (p < text_.size() && (text_[p] == 'e' || text_[p] == 'E')) {
            ++p;
            if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
            if (p >= text_.size() || !isDigit(text_[p]))
                fail(p, "expected digits after the exponent of '" +
                            text_.substr(start, p - start) + "'");
            while (p < text_.size() && isDigit(text_[p])) ++p;
        }
        if (p < text_.size() && isIdentChar(text_[p]))  // "2Dp", "1e5x"
            fail(p, "unexpected '" + std::string(1, text_[p]) + "' after the number '" +
                        text_.substr(start, p - start) + "'");
        double v = 0;
        const auto r = std::from_chars(text_.data() + start, text_.data() + p, v);
        if (r.ec != std::errc() || !std::isfinite(v))
            fail(start, "the number '" + text_.substr(start, p - start) + "' is out of range");
        pos_ = p;
        return v;
    }

    std::string parseIdentifier() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && isIdentChar(text_[pos_])) ++pos_;
        return text_.substr(start, pos_ - start);
    }

    /// variable | variable[index] | function(args)
    double parseName() {
        const std::size_t start = pos_;
        const std::string name = parseIdentifier();
        if (accept("(")) return parseCall(name, start);
        if (accept("[")) {
            const std::size_t index_at = pos_;
            const double index = parseOr();
            expect(']');
            if (skip_ > 0) return 0;
            if (index != std::floor(index) || index < 0 || index > 1e9)
                fail(index_at, "the index of '" + name + "[...]' is " + fmt(index) +
                                   ", expected a non-negative integer");
            const std::string element = name + std::to_string(static_cast<long long>(index));
            if (!ev_.has(element))
                throw ExpressionError("unknown variable '" + element + "' (from '" + name + "[" +
                                      fmt(index) + "]') in '" + text_ + "' at position " +
                                      std::to_string(start));
            return ev_.value(element);
        }
        if (!ev_.has(name)) {
            std::string hint;
            for (const FunctionSpec& f : kFunctions)
                if (name == f.name) hint = " (for the function write '" + name + "(...)')";
            throw ExpressionError("unknown variable '" + name + "' in '" + shown() +
                                  "' at position " + std::to_string(start) + hint);
        }
        return ev_.value(name);
    }

    /// Called after `name(`; parses the arguments and the closing ')'.
    double parseCall(const std::string& name, std::size_t at) {
        for (const char* u : kUnsupportedFunctions)
            if (name == u) fail(at, "function '" + name + "' is not supported by SeaSpring");
        const FunctionSpec* f = nullptr;
        for (const FunctionSpec& g : kFunctions)
            if (name == g.name) f = &g;
        if (!f) fail(at, "unknown function '" + name + "'");

        std::vector<double> args;
        if (!accept(")")) {
            for (;;) {
                // eval(c,a,b): the branch not taken is parsed without value checks.
                const bool skip_this = name == "eval" && ((args.size() == 1 && args[0] == 0) ||
                                                          (args.size() == 2 && args[0] != 0));
                skip_ += skip_this;
                args.push_back(parseOr());
                skip_ -= skip_this;
                if (accept(")")) break;
                if (!accept(","))
                    fail(pos_, "expected ',' or ')' in the arguments of '" + name +
                                   "' but found " + describeHere());
            }
        }
        const int n = static_cast<int>(args.size());
        if (n < f->min_args || (f->max_args >= 0 && n > f->max_args))
            fail(at, "function '" + name + "' expects " + (f->max_args < 0 ? "at least " : "") +
                         std::to_string(f->min_args) +
                         (f->min_args == 1 ? " argument, got " : " arguments, got ") +
                         std::to_string(n));
        const std::string call = name + "(...)";
        if (f->fn) return checked(f->fn(args), at, call);
        if (name == "eval") return args[0] != 0 ? args[1] : args[2];
        if (skip_ > 0) return 0;
        if (name == "roundpos") {
            if (args[2] == 0) fail(at, "roundpos(pos,posmin,dp) needs dp != 0");
            return checked(args[1] + std::round((args[0] - args[1]) / args[2]) * args[2], at, call);
        }
        if (dp_ == 0)
            fail(at, "function '" + name + "' needs the grid (definition dp and pointref), "
                     "which is not set yet");
        const double o = name == "roundposx"   ? origin_.x
                         : name == "roundposy" ? origin_.y
                                               : origin_.z;
        return checked(o + std::round((args[0] - o) / dp_) * dp_, at, call);
    }

    const std::string& text_;
    const ExpressionEvaluator& ev_;
    Vec3d origin_;
    double dp_;
    std::size_t pos_ = 0;
    int skip_ = 0;
    int depth_ = 0;  ///< parseUnary calls in progress
};

}  // namespace

void ExpressionEvaluator::define(const std::string& name, double value, bool constant) {
    if (!isIdentifier(name))
        throw ExpressionError("'" + name +
                              "' is not a valid variable name (expected a letter or '_' "
                              "followed by letters, digits or '_')");
    if (!std::isfinite(value))
        throw ExpressionError("variable '" + name + "' cannot be set to the non-finite value " +
                              fmt(value));
    const auto it = vars_.find(name);
    if (it != vars_.end() && it->second.constant)
        throw ExpressionError("cannot redefine the constant '" + name + "' (value " +
                              fmt(it->second.value) + ") with the value " + fmt(value));
    vars_[name] = Variable{value, constant};
}

void ExpressionEvaluator::assign(const std::string& name, double value) {
    const auto it = vars_.find(name);
    if (it == vars_.end())
        throw ExpressionError("cannot set unknown variable '" + name + "' (define it first)");
    if (it->second.constant)
        throw ExpressionError("cannot change the constant '" + name + "' (value " +
                              fmt(it->second.value) + ") to " + fmt(value));
    if (!std::isfinite(value))
        throw ExpressionError("variable '" + name + "' cannot be set to the non-finite value " +
                              fmt(value));
    it->second.value = value;
}

bool ExpressionEvaluator::has(const std::string& name) const { return vars_.count(name) != 0; }

double ExpressionEvaluator::value(const std::string& name) const {
    const auto it = vars_.find(name);
    if (it == vars_.end()) throw ExpressionError("unknown variable '" + name + "'");
    return it->second.value;
}

void ExpressionEvaluator::setGrid(Vec3d origin, double dp) {
    if (!(dp > 0) || !std::isfinite(dp))
        throw ExpressionError("grid dp must be a positive finite number, got " + fmt(dp));
    grid_origin_ = origin;
    grid_dp_ = dp;
}

double ExpressionEvaluator::evaluate(const std::string& text) const {
    return Parser(text, *this, grid_origin_, grid_dp_).run();
}

}  // namespace seaspring::gencase
