// The steps of instantiating one connection from its rule, which the connections stage
// (connections.cpp) runs in order: its arguments checked and bound, its label, its unknowns
// (connection_arguments.cpp); its loads (connections.cpp); its constraints
// (connection_constraints.cpp); its conditions, notes and checks (connections.cpp).
#pragma once

#include <string>

#include "model/builder/context.hpp"

namespace tackle::build {

// Whether a rule entry with this `when` applies to the connection: always, when it gives the
// optional argument named, or in a problem with the number of axes named ("3-D").
bool applies(const BuildContext& ctx, const ConnectionDesc& c, const std::string& when);

// The connection gives what its rule needs, and the rule is for this many axes.
bool arguments_fit(BuildContext& ctx, const Instance& in);

// Resolves every argument: bodies and points by name (bound as position vectors in the
// rule's scope), paths, expressions, vectors and moments.
bool bind_arguments(BuildContext& ctx, Instance& in);

// A one-body contact (a body against the ground) placed at a point of another body that
// moves: reported (the contact's force on the other body would be missing).
bool at_point_of_another_body(BuildContext& ctx, const Instance& in);

// "string s", "pulley at C", "force on A": how reports name the connection.
std::string label_of(const Instance& in);

// `across` checks, before the loads are made of the vectors.
bool vectors_fit(BuildContext& ctx, const Instance& in);

// The rule's unknowns, named for the connection and bound in its scope.
bool make_unknowns(BuildContext& ctx, Instance& in);

// The rule's constraints, into m.constraints.
void add_constraints(BuildContext& ctx, Instance& in);

}  // namespace tackle::build
