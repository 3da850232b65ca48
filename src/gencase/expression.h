// SeaSpring — MIT licence.
/// \file expression.h
/// \brief GenCase-style arithmetic expressions and variables (`newvar`, `#expr`).
///
/// Grammar (lowest to highest precedence):
///   ternary-free; `||`, `&&`, comparisons (== != < <= > >=), + -, * / %, unary + - !, ^ (power,
///   right-assoc), primary: number | variable | variable[index-expr] | function(args) | ( expr ).
/// Variables are case-sensitive. `x[1+1]` reads variable `x2` (GenCase array syntax).
/// Functions: pi() e() float int floor ceil round abs fmod fmodr sqrt exp log log10 pow
///   sin cos tan sindg cosdg tandg sinh cosh tanh asin acos atan atan2 min max (2+ args)
///   eval(cond,a,b) roundpos(pos,posmin,dp) roundposx roundposy roundposz (need setGrid()).
/// A NaN or infinite result is an error.
#pragma once

#include <map>
#include <string>

#include "case/xml_source.h"
#include "core/vec3.h"

namespace seaspring::gencase {

/// Raised for a malformed expression, an unknown variable or function, or a NaN result
/// (the case model's ValueError, which XmlSource turns into "file:line: ..." messages).
/// The message names the expression and the problem; callers add file:line.
using ExpressionError = model::ValueError;

/// The `#...` values of the case definition (XmlSource takes it as its ValueEvaluator).
class ExpressionEvaluator : public model::ValueEvaluator {
public:
    /// Defines or overwrites a variable. `constant` ones cannot be changed later (setvar
    /// on a constant is an error).
    void define(const std::string& name, double value, bool constant = false);
    /// Changes an existing variable (GenCase `setvar`); error if unknown or constant.
    void assign(const std::string& name, double value);
    bool has(const std::string& name) const;
    double value(const std::string& name) const;

    /// Grid used by roundpos*: positions are rounded to origin + k*dp.
    void setGrid(Vec3d origin, double dp);

    /// Evaluates `text` (without a leading '#').
    double evaluate(const std::string& text) const override;

private:
    struct Variable { double value; bool constant; };
    std::map<std::string, Variable> vars_;
    Vec3d grid_origin_{0, 0, 0};
    double grid_dp_ = 0;
};

}  // namespace seaspring::gencase
