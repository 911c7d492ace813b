// The stages that build a Model, in the order build_model runs them. Each fills its part of
// ctx.m (and of the symbol table) from the description and reports its problems to
// ctx.diags; every problem is thrown at once after the last stage.
#pragma once

#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "model/builder/context.hpp"

namespace tackle::build {

// m.axes and m.axis from 'axes' (one axis, x, when absent); needs nothing.
void axes(BuildContext& ctx);
// The parameters in the symbol table (dimension, unit, sign, value, range); needs nothing.
void parameters(BuildContext& ctx);
// m.steady from 'steady': the unknown rate's square, the rate's name read as its root, the
// rate and period reported, the condition that the rate is real; needs the parameters.
void steady(BuildContext& ctx);
// m.bodies (each a point too), their coordinates, accelerations and masses; needs the axes and parameters.
void bodies(BuildContext& ctx);
// The named points of m.points (fixed, or on a body); needs the bodies.
void points(BuildContext& ctx);
// ctx.layout, the values that tell strand directions; needs the parameters and the coordinates.
void read_layout(BuildContext& ctx);
// Rule instances: unknowns, loads, constraints, conditions, turning lengths; needs the points and layout.
void connections(BuildContext& ctx);
// m.gravity and each massive body's weight in m.loads; needs the bodies' masses and centers of mass.
void gravity(BuildContext& ctx);
// m.given (taken out of m.candidates) and m.wanted; needs every symbol, the rules' unknowns included.
void given_and_find(BuildContext& ctx);
// Each constraint's constant, when a coordinate is asked for; needs m.constraints and m.wanted.
void constraint_constants(BuildContext& ctx);
// m.derive, the balances and constraints asked for; needs the bodies, points and constraints.
void derive(BuildContext& ctx);

// m.motion from 'motion': the independent coordinates (checked against the constraints'
// rates, as many as the degrees of freedom), their initial values, simulate's defaults; the
// coordinates and rates become given. Needs the constraints and m.given.
void motion(BuildContext& ctx);

// m.interval from 'interval': the rates at its start and end, its duration or distance.
// Needs the bodies and parameters.
void interval(BuildContext& ctx);

// m.impact from 'impact': the rates just before, plastic or a restitution, the symbols of the
// impulses and of the energy lost; an impact admits no connections, loads or questions.
// Needs the bodies, parameters and connections.
void impact(BuildContext& ctx);

// m.statement: each {name} in it a parameter (questions.cpp). Needs the parameters.
void statement(BuildContext& ctx);

// Helpers one stage lends another.

// The value of a `given` entry in SI, a number or an expression in the parameters
// (questions.cpp); read_layout uses it too.
std::optional<GiNaC::ex> given_value(const GivenDesc& g, const SymbolInfo& s, const SymbolTable& table, Diagnostics& to,
                                     std::string* unit_text = nullptr, GiNaC::ex* to_si = nullptr);

// The path of a points argument, made once (paths.cpp); the connections stage uses it.
const Path* path_of(BuildContext& ctx, Instance& in, const std::string& key);

}  // namespace tackle::build
