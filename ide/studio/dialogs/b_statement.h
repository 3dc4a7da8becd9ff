#pragma once
// The B statement of computed mass properties, as `padrob inertia` writes it
// (ide/cli/inertia.cpp; re-implemented here on QString, the CLI stays as it is):
//   B id m Ixx Iyy Izz Ixy Iyz Ixz CG x y z
// with 6 significant digits, and values negligible next to the body's size written
// as 0 (no "-1e-17"). A line that already holds the body's B statement keeps its
// indentation, its NAME and its trailing comment when the statement is replaced.

#include "solver/inertia/solid_inertia.h"
#include "solver/spec/model_spec.h"

#include <QString>

namespace studio::bstatement {

/// `v` with 6 significant digits, shortest form ("0" for zero).
QString number(double v);

/// "B id m Ixx Iyy Izz Ixy Iyz Ixz CG x y z" of computed mass properties (products
/// as tensor elements, Ixy = −∫xy dm, as the model language has them).
QString format(int id, const solver::MassProperties& p);

/// `NAME "text"` with the quote and backslash escaped; "" for an empty name.
QString nameToken(const std::string& name);

/// The B statement of a body as the spec holds it (when no source text is at hand):
/// "B id [m Ixx Iyy Izz [Ixy Iyz Ixz]] [CG x y z] [NAME "…"]".
QString fromSpec(const solver::BodySpec& body);

/// `line` (a whole source line holding a B statement) with that statement replaced by
/// `statement`: the indentation, the NAME as written and a trailing comment (// or #)
/// are kept, the comment at its column when there is room. "" when `line` does not
/// start with a B statement or its strings are not closed.
QString replaceInLine(const QString& line, const QString& statement);

}  // namespace studio::bstatement
