#pragma once
// Writes a ModelSpec back as model-language text. Parsing the output gives the
// same model (values exact: numbers are written in their shortest round-trip form).

#include "solver/spec/model_spec.h"

#include <string>

namespace solver::parse {

/// The model as text: GRAVITY, bodies, joints with their lines, drives, forces,
/// graphics, in that order and each in file order. Comments are not kept.
std::string writeModel(const ModelSpec& spec);

/// Shortest decimal text that reads back as exactly `v`.
std::string formatNumber(double v);

}  // namespace solver::parse
