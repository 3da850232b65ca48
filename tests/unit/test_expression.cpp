// SeaSpring — MIT licence.
/// \file test_expression.cpp
/// \brief Tests of the GenCase-style expression evaluator (gencase/expression.h).
#include "gencase/expression.h"

#include <gtest/gtest.h>

#include <string>

using seaspring::Vec3d;
using seaspring::gencase::ExpressionError;
using seaspring::gencase::ExpressionEvaluator;

namespace {

/// Runs `f`, expects an ExpressionError and returns its message ("" if none was thrown).
template <typename F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const ExpressionError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no ExpressionError was thrown";
    return "";
}

std::string evalError(const ExpressionEvaluator& ev, const std::string& text) {
    return errorOf([&] { ev.evaluate(text); });
}

#define EXPECT_CONTAINS(haystack, needle)                            \
    EXPECT_NE(std::string(haystack).find(needle), std::string::npos) \
        << "message: " << (haystack) << "\nexpected to contain: " << (needle)

}  // namespace

TEST(Expression, Numbers) {
    ExpressionEvaluator ev;
    EXPECT_EQ(ev.evaluate("1"), 1.0);
    EXPECT_EQ(ev.evaluate("1.5"), 1.5);
    EXPECT_EQ(ev.evaluate(".5"), 0.5);
    EXPECT_EQ(ev.evaluate("2."), 2.0);
    EXPECT_EQ(ev.evaluate("1e-3"), 0.001);
    EXPECT_EQ(ev.evaluate("2.5E+2"), 250.0);
    EXPECT_EQ(ev.evaluate("3e2"), 300.0);
    EXPECT_EQ(ev.evaluate("0.0085"), 0.0085);
    EXPECT_EQ(ev.evaluate("  \t7 \n"), 7.0);
}

struct PrecedenceCase {
    const char* text;
    double value;
};

TEST(Expression, PrecedenceAndAssociativity) {
    // clang-format off
    const PrecedenceCase cases[] = {
        {"1+2*3", 7},        {"(1+2)*3", 9},       {"10-4-3", 3},       {"2*3/4", 1.5},
        {"12/3/2", 2},       {"7%4", 3},           {"-7%4", -3},        {"7.5%2", 1.5},
        {"1+7%4*2", 7},      {"2^3", 8},           {"2^3^2", 512},      {"(2^3)^2", 64},
        {"-2^2", -4},        {"(-2)^2", 4},        {"2^-1", 0.5},       {"-2^-2", -0.25},
        {"2*3^2", 18},       {"--3", 3},           {"+-+3", -3},        {"!0", 1},
        {"!5", 0},           {"!!5", 1},           {"!0+1", 2},         {"-3+5", 2},
        {"1<2", 1},          {"2<1", 0},           {"2<=2", 1},         {"3>=4", 0},
        {"3>2", 1},          {"1<2<3", 1},         {"3>2>1", 0},        {"1+1==2", 1},
        {"1==2", 0},         {"1!=2", 1},          {"2==2==1", 1},      {"1<2==1", 1},
        {"1&&1", 1},         {"1&&0", 0},          {"0||0", 0},         {"0||3", 1},
        {"1||0&&0", 1},      {"(1||0)&&0", 0},     {"2>1&&3>2", 1},     {"1+2>2&&!0", 1},
        {" 1 + 2 * ( 3 - 1 ) ", 5}, {"0.5*4-1", 1},
    };
    // clang-format on
    ExpressionEvaluator ev;
    for (const PrecedenceCase& c : cases) EXPECT_EQ(ev.evaluate(c.text), c.value) << c.text;
}

TEST(Expression, VariablesAndArrays) {
    ExpressionEvaluator ev;
    ev.define("Dp", 0.01);
    ev.define("Tank_px1", 2);
    ev.define("x1", 10);
    ev.define("x2", 20);
    ev.define("x12", 120);
    EXPECT_TRUE(ev.has("Dp"));
    EXPECT_FALSE(ev.has("dp"));  // case-sensitive
    EXPECT_EQ(ev.value("Dp"), 0.01);
    EXPECT_EQ(ev.evaluate("Tank_px1+4*Dp"), 2.0 + 4 * 0.01);
    EXPECT_EQ(ev.evaluate("x[1+1]"), 20);
    EXPECT_EQ(ev.evaluate("x[ 1 ]*2"), 20);
    EXPECT_EQ(ev.evaluate("x[x1+2]"), 120);
    EXPECT_EQ(ev.evaluate("x[3*0.5+0.5]"), 20);
    ev.assign("x2", 5);
    EXPECT_EQ(ev.evaluate("x[2]"), 5);
    ev.define("x2", 6);  // newvar on an existing non-constant overwrites
    EXPECT_EQ(ev.value("x2"), 6);
    // A variable may share a function's name; `sin` alone is the variable.
    ev.define("sin", 3);
    EXPECT_EQ(ev.evaluate("sin+sin(0)"), 3);
}

TEST(Expression, Constants) {
    ExpressionEvaluator ev;
    ev.define("Dp", 0.01, true);
    EXPECT_EQ(ev.evaluate("Dp*2"), 0.02);
    std::string m = errorOf([&] { ev.define("Dp", 0.02); });
    EXPECT_CONTAINS(m, "constant 'Dp'");
    EXPECT_CONTAINS(m, "0.02");
    m = errorOf([&] { ev.define("Dp", 0.02, true); });
    EXPECT_CONTAINS(m, "constant 'Dp'");
    m = errorOf([&] { ev.assign("Dp", 0.03); });
    EXPECT_CONTAINS(m, "constant 'Dp'");
    EXPECT_CONTAINS(m, "0.03");
    EXPECT_EQ(ev.value("Dp"), 0.01);  // unchanged by the failed attempts
    // A non-constant may be turned into a constant by define.
    ev.define("H", 1);
    ev.define("H", 2, true);
    EXPECT_EQ(ev.value("H"), 2);
    EXPECT_THROW(ev.assign("H", 3), ExpressionError);
}

TEST(Expression, VariableErrors) {
    ExpressionEvaluator ev;
    EXPECT_CONTAINS(errorOf([&] { ev.assign("Foo", 1); }), "unknown variable 'Foo'");
    EXPECT_CONTAINS(errorOf([&] { ev.value("Foo"); }), "unknown variable 'Foo'");
    EXPECT_CONTAINS(errorOf([&] { ev.define("2x", 1); }), "'2x' is not a valid variable name");
    EXPECT_CONTAINS(errorOf([&] { ev.define("a-b", 1); }), "'a-b' is not a valid variable name");
    EXPECT_CONTAINS(errorOf([&] { ev.define("", 1); }), "is not a valid variable name");
    EXPECT_CONTAINS(errorOf([&] { ev.define("a", 1.0 / 0.0 * 0.0); }), "non-finite");
    ev.define("a", 1);
    EXPECT_CONTAINS(errorOf([&] { ev.assign("a", 1e308 * 10); }), "non-finite value inf");
    EXPECT_EQ(ev.value("a"), 1);
}

TEST(Expression, Functions) {
    ExpressionEvaluator ev;
    const double pi = 3.14159265358979323846;
    EXPECT_EQ(ev.evaluate("pi()"), pi);
    EXPECT_EQ(ev.evaluate("e()"), 2.71828182845904523536);
    EXPECT_EQ(ev.evaluate("float(2.5)"), 2.5);
    EXPECT_EQ(ev.evaluate("int(2.7)"), 2);
    EXPECT_EQ(ev.evaluate("int(-2.7)"), -2);
    EXPECT_EQ(ev.evaluate("floor(-2.5)"), -3);
    EXPECT_EQ(ev.evaluate("floor(2.5)"), 2);
    EXPECT_EQ(ev.evaluate("ceil(2.1)"), 3);
    EXPECT_EQ(ev.evaluate("ceil(-2.1)"), -2);
    EXPECT_EQ(ev.evaluate("round(2.5)"), 3);
    EXPECT_EQ(ev.evaluate("round(-2.5)"), -3);
    EXPECT_EQ(ev.evaluate("round(2.4999)"), 2);
    EXPECT_EQ(ev.evaluate("abs(-3.5)"), 3.5);
    EXPECT_EQ(ev.evaluate("fmod(7,3)"), 1);
    EXPECT_EQ(ev.evaluate("fmod(-7,3)"), -1);
    EXPECT_EQ(ev.evaluate("fmodr(-7,3)"), 2);  // -7 - 3*floor(-7/3) = -7 + 9
    EXPECT_EQ(ev.evaluate("fmodr(7,3)"), 1);
    EXPECT_EQ(ev.evaluate("fmodr(-0.5,2)"), 1.5);
    EXPECT_EQ(ev.evaluate("sqrt(16)"), 4);
    EXPECT_EQ(ev.evaluate("exp(0)"), 1);
    EXPECT_DOUBLE_EQ(ev.evaluate("exp(1)"), 2.71828182845904523536);
    EXPECT_EQ(ev.evaluate("log(1)"), 0);
    EXPECT_DOUBLE_EQ(ev.evaluate("log(e()^2)"), 2);
    EXPECT_EQ(ev.evaluate("log10(1000)"), 3);
    EXPECT_EQ(ev.evaluate("pow(2,10)"), 1024);
    EXPECT_EQ(ev.evaluate("pow(9,0.5)"), 3);
    EXPECT_EQ(ev.evaluate("sin(0)"), 0);
    EXPECT_DOUBLE_EQ(ev.evaluate("sin(pi()/6)"), 0.5);
    EXPECT_EQ(ev.evaluate("cos(0)"), 1);
    EXPECT_DOUBLE_EQ(ev.evaluate("cos(pi()/3)"), 0.5);
    EXPECT_DOUBLE_EQ(ev.evaluate("tan(pi()/4)"), 1);
    EXPECT_DOUBLE_EQ(ev.evaluate("sindg(30)"), 0.5);
    EXPECT_DOUBLE_EQ(ev.evaluate("cosdg(60)"), 0.5);
    EXPECT_DOUBLE_EQ(ev.evaluate("tandg(45)"), 1);
    EXPECT_DOUBLE_EQ(ev.evaluate("sindg(-90)"), -1);
    EXPECT_EQ(ev.evaluate("sinh(0)"), 0);
    EXPECT_DOUBLE_EQ(ev.evaluate("sinh(1)"),
                     (2.71828182845904523536 - 1 / 2.71828182845904523536) / 2);
    EXPECT_EQ(ev.evaluate("cosh(0)"), 1);
    EXPECT_DOUBLE_EQ(ev.evaluate("cosh(1)"),
                     (2.71828182845904523536 + 1 / 2.71828182845904523536) / 2);
    EXPECT_EQ(ev.evaluate("tanh(0)"), 0);
    EXPECT_DOUBLE_EQ(ev.evaluate("tanh(1)"),
                     (2.71828182845904523536 * 2.71828182845904523536 - 1) /
                         (2.71828182845904523536 * 2.71828182845904523536 + 1));
    EXPECT_DOUBLE_EQ(ev.evaluate("asin(0.5)"), pi / 6);
    EXPECT_DOUBLE_EQ(ev.evaluate("acos(0.5)"), pi / 3);
    EXPECT_EQ(ev.evaluate("acos(1)"), 0);
    EXPECT_DOUBLE_EQ(ev.evaluate("atan(1)"), pi / 4);
    EXPECT_DOUBLE_EQ(ev.evaluate("atan2(1,-1)"), 3 * pi / 4);
    EXPECT_DOUBLE_EQ(ev.evaluate("atan2(-1,0)"), -pi / 2);
    EXPECT_EQ(ev.evaluate("min(3,1)"), 1);
    EXPECT_EQ(ev.evaluate("min(3,-1,2,0)"), -1);
    EXPECT_EQ(ev.evaluate("max(3,1)"), 3);
    EXPECT_EQ(ev.evaluate("max(3,-1,7,0)"), 7);
    EXPECT_EQ(ev.evaluate("eval(1,2,3)"), 2);
    EXPECT_EQ(ev.evaluate("eval(0,2,3)"), 3);
    EXPECT_EQ(ev.evaluate("eval(2>1,10,20)"), 10);
    EXPECT_EQ(ev.evaluate("roundpos(0.26,0,0.1)"), 3 * 0.1);  // 0 + round(2.6)*0.1
    EXPECT_EQ(ev.evaluate("roundpos(1.12,1,0.25)"), 1);       // 1 + round(0.48)*0.25
    EXPECT_EQ(ev.evaluate("roundpos(1.2,1,0.25)"), 1.25);     // 1 + round(0.8)*0.25
    EXPECT_EQ(ev.evaluate(" max ( 1 , sqrt( 4 ) ) "), 2);
    EXPECT_EQ(ev.evaluate("2*sqrt(9)^2"), 18);  // (sqrt(9))^2 * 2
}

TEST(Expression, LazyBranches) {
    ExpressionEvaluator ev;
    ev.define("n", 0);
    EXPECT_EQ(ev.evaluate("eval(n>0, 1/n, -1)"), -1);
    EXPECT_EQ(ev.evaluate("eval(n==0, 7, sqrt(-1))"), 7);
    EXPECT_EQ(ev.evaluate("eval(n>0, x[n-1], 5)"), 5);  // x-1 would be no name
    EXPECT_EQ(ev.evaluate("n!=0 && 1/n>2"), 0);
    EXPECT_EQ(ev.evaluate("n==0 || 1/n>2"), 1);
    // The skipped branch is still checked for typos and syntax.
    EXPECT_CONTAINS(evalError(ev, "eval(n>0, Nn, 1)"), "unknown variable 'Nn'");
    EXPECT_CONTAINS(evalError(ev, "eval(n>0, foo(1), 1)"), "unknown function 'foo'");
    EXPECT_CONTAINS(evalError(ev, "n!=0 && (1"), "expected ')'");
}

TEST(Expression, RoundPosOnGrid) {
    ExpressionEvaluator ev;
    EXPECT_CONTAINS(evalError(ev, "roundposx(0.1)"),
                    "in 'roundposx(0.1)' at position 0: function 'roundposx' needs the grid");
    EXPECT_CONTAINS(evalError(ev, "roundposz(1)"), "'roundposz' needs the grid");
    ev.setGrid(Vec3d{0, 0, 0}, 0.025);
    EXPECT_EQ(ev.evaluate("roundposx(0.1)"), 0.1);         // round(4)*0.025
    EXPECT_EQ(ev.evaluate("roundposx(0.11)"), 0.1);        // round(4.4)=4
    EXPECT_EQ(ev.evaluate("roundposy(0.114)"), 0.125);     // round(4.56)=5 -> 5*0.025
    EXPECT_EQ(ev.evaluate("roundposz(-0.0374)"), -0.025);  // round(-1.496)=-1
    EXPECT_EQ(ev.evaluate("roundposz(-0.038)"), -0.05);    // round(-1.52)=-2
    ev.setGrid(Vec3d{-0.25, 0.01, 0.505}, 0.025);
    EXPECT_EQ(ev.evaluate("roundposx(0.01)"), -0.25 + 10 * 0.025);  // 0.26/0.025 = 10.4
    EXPECT_EQ(ev.evaluate("roundposx(-0.3)"), -0.25 + -2 * 0.025);  // -0.05/0.025 = -2
    EXPECT_EQ(ev.evaluate("roundposy(1.03)"), 0.01 + 41 * 0.025);   // 1.02/0.025 = 40.8
    EXPECT_EQ(ev.evaluate("roundposz(0.5)"), 0.505);                // -0.005/0.025 = -0.2
    EXPECT_EQ(ev.evaluate("roundposz(0.56)"), 0.505 + 2 * 0.025);   // 0.055/0.025 = 2.2
    EXPECT_CONTAINS(errorOf([&] { ev.setGrid(Vec3d{0, 0, 0}, 0); }), "grid dp must be a positive");
    EXPECT_CONTAINS(errorOf([&] { ev.setGrid(Vec3d{0, 0, 0}, -0.1); }), "-0.1");
}

TEST(Expression, SyntaxErrors) {
    ExpressionEvaluator ev;
    ev.define("Dp", 0.01);
    EXPECT_CONTAINS(evalError(ev, "Dp*(2+"),
                    "in 'Dp*(2+' at position 6: expected a number, variable, function or '(' but "
                    "found end of expression");
    EXPECT_CONTAINS(evalError(ev, "Dp*(2+1"), "in 'Dp*(2+1' at position 7: expected ')'");
    EXPECT_CONTAINS(evalError(ev, "x[1"), "in 'x[1' at position 3: expected ']'");
    EXPECT_CONTAINS(evalError(ev, ""), "in '' at position 0: empty expression");
    EXPECT_CONTAINS(evalError(ev, "   "), "at position 3: empty expression");
    EXPECT_CONTAINS(evalError(ev, "1 2"), "in '1 2' at position 2: unexpected '2'");
    EXPECT_CONTAINS(evalError(ev, "2Dp"),
                    "in '2Dp' at position 1: unexpected 'D' after the number '2'");
    EXPECT_CONTAINS(evalError(ev, "1e+"),
                    "in '1e+' at position 3: expected digits after the exponent of '1e+'");
    EXPECT_CONTAINS(evalError(ev, "1e400"), "at position 0: the number '1e400' is out of range");
    EXPECT_CONTAINS(evalError(ev, ". 5"), "in '. 5' at position 0: expected digits in a number");
    EXPECT_CONTAINS(evalError(ev, "1 = 1"), "at position 2: unexpected '=' (comparison is '==')");
    EXPECT_CONTAINS(evalError(ev, "1 & 1"), "at position 2: unexpected '&' (use '&&')");
    EXPECT_CONTAINS(evalError(ev, "1 | 1"), "at position 2: unexpected '|' (use '||')");
    EXPECT_CONTAINS(evalError(ev, "1+*2"), "in '1+*2' at position 2: expected a number");
    EXPECT_CONTAINS(evalError(ev, "max(1;2)"),
                    "at position 5: expected ',' or ')' in the arguments of 'max'");
    EXPECT_CONTAINS(evalError(ev, "max(1,)"), "at position 6: expected a number");
    EXPECT_CONTAINS(evalError(ev, "1)"), "at position 1: unexpected ')'");
    EXPECT_CONTAINS(evalError(ev, "#Dp"),
                    "at position 0: expected a number, variable, function or '(' but found '#'");
}

TEST(Expression, NameErrors) {
    ExpressionEvaluator ev;
    ev.define("x1", 1);
    ev.define("x2", 2);
    EXPECT_CONTAINS(evalError(ev, "Foo+1"), "unknown variable 'Foo' in 'Foo+1' at position 0");
    EXPECT_CONTAINS(evalError(ev, "1 + dp"), "unknown variable 'dp' in '1 + dp' at position 4");
    EXPECT_CONTAINS(
        evalError(ev, "2*pi"),
        "unknown variable 'pi' in '2*pi' at position 2 (for the function write 'pi(...)')");
    EXPECT_CONTAINS(evalError(ev, "x[3]"),
                    "unknown variable 'x3' (from 'x[3]') in 'x[3]' at position 0");
    EXPECT_CONTAINS(
        evalError(ev, "x[1.5]"),
        "in 'x[1.5]' at position 2: the index of 'x[...]' is 1.5, expected a non-negative integer");
    EXPECT_CONTAINS(evalError(ev, "x[0-1]"), "the index of 'x[...]' is -1");
    EXPECT_CONTAINS(evalError(ev, "1+foo(2)"),
                    "in '1+foo(2)' at position 2: unknown function 'foo'");
    for (const char* f : {"rand", "randint", "randinit", "wavelength"}) {
        const std::string text = std::string("1+") + f + "(1,2)";
        EXPECT_CONTAINS(evalError(ev, text), "in '" + text + "' at position 2: function '" + f +
                                                 "' is not supported by SeaSpring");
    }
}

TEST(Expression, ArgumentCountErrors) {
    ExpressionEvaluator ev;
    ev.setGrid(Vec3d{0, 0, 0}, 0.1);
    EXPECT_CONTAINS(evalError(ev, "sqrt(1,2)"),
                    "in 'sqrt(1,2)' at position 0: function 'sqrt' expects 1 argument, got 2");
    EXPECT_CONTAINS(evalError(ev, "1+sin()"),
                    "at position 2: function 'sin' expects 1 argument, got 0");
    EXPECT_CONTAINS(evalError(ev, "pi(1)"), "function 'pi' expects 0 arguments, got 1");
    EXPECT_CONTAINS(evalError(ev, "e(1)"), "function 'e' expects 0 arguments, got 1");
    EXPECT_CONTAINS(evalError(ev, "pow(2)"), "function 'pow' expects 2 arguments, got 1");
    EXPECT_CONTAINS(evalError(ev, "atan2(1,2,3)"), "function 'atan2' expects 2 arguments, got 3");
    EXPECT_CONTAINS(evalError(ev, "min(1)"), "function 'min' expects at least 2 arguments, got 1");
    EXPECT_CONTAINS(evalError(ev, "max()"), "function 'max' expects at least 2 arguments, got 0");
    EXPECT_CONTAINS(evalError(ev, "eval(1,2)"), "function 'eval' expects 3 arguments, got 2");
    EXPECT_CONTAINS(evalError(ev, "roundpos(1,2)"),
                    "function 'roundpos' expects 3 arguments, got 2");
    EXPECT_CONTAINS(evalError(ev, "roundposy(1,2)"),
                    "function 'roundposy' expects 1 argument, got 2");
}

TEST(Expression, NonFiniteErrors) {
    ExpressionEvaluator ev;
    ev.define("Zero", 0);
    EXPECT_CONTAINS(evalError(ev, "1/0"),
                    "'1/0' gives a non-finite value: '/' at position 1 gives inf");
    EXPECT_CONTAINS(evalError(ev, "2+1/(Zero)"),
                    "'2+1/(Zero)' gives a non-finite value: '/' at position 3");
    EXPECT_CONTAINS(evalError(ev, "-1/0"), "gives -inf");
    EXPECT_CONTAINS(evalError(ev, "0/0"), "'0/0' gives a non-finite value");
    EXPECT_CONTAINS(evalError(ev, "1/(1/0)"),
                    "'1/(1/0)' gives a non-finite value: '/' at position 4");
    EXPECT_CONTAINS(evalError(ev, "5%0"), "'5%0' gives a non-finite value: '%' at position 1");
    EXPECT_CONTAINS(evalError(ev, "1e300*1e300"), "'*' at position 5 gives inf");
    EXPECT_CONTAINS(evalError(ev, "1e308+1e308"), "'+' at position 5 gives inf");
    EXPECT_CONTAINS(evalError(ev, "-1e308-1e308"), "'-' at position 6 gives -inf");
    EXPECT_CONTAINS(evalError(ev, "10^400"), "'^' at position 2 gives inf");
    EXPECT_CONTAINS(evalError(ev, "1+sqrt(-1)"),
                    "'1+sqrt(-1)' gives a non-finite value: sqrt(...) at position 2");
    EXPECT_CONTAINS(evalError(ev, "log(0)"), "log(...) at position 0 gives -inf");
    EXPECT_CONTAINS(evalError(ev, "asin(2)"), "asin(...) at position 0");
    EXPECT_CONTAINS(evalError(ev, "fmodr(1,0)"), "fmodr(...) at position 0");
    EXPECT_CONTAINS(evalError(ev, "roundpos(1,0,0)"),
                    "in 'roundpos(1,0,0)' at position 0: roundpos(pos,posmin,dp) needs dp != 0");
}
