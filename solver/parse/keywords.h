#pragma once
// The words of the model language (docs/model-language.md), in one place: the statements
// a line may start with (the parser's "did you mean" suggestions) and every other keyword
// (options, drive and force kinds, shapes, magnitude laws), which the studio's editor
// highlights and completes.

#include <array>

namespace solver::keywords {

/// The statements a line may start with.
inline constexpr std::array kStatements = {"GRAVITY", "RESTITUTION", "B",  "C",     "B1",   "B2",     "CL1",
                                           "CL2",     "D",           "F",  "G",     "FLUID", "PUMP", "CONTACT"};

/// Every other word: options of bodies and joints, drives (HYD, MOTOR, PNEU, SERVO, CYL,
/// HMOTOR) and their options, fluid power, forces and magnitudes, graphics, contact.
inline constexpr std::array kOptions = {
    "T",     "LL",       "UL",     "QI",        "VI",     "NAME",   "CG",     "P1",      "A1",        "R1",
    "P2",    "A2",       "R2",     "DEG",       "HYD",    "VMAX",   "VMIN",   "FMAX",    "FMIN",      "PUMP",
    "RPM",   "BORE",     "ROD",    "PRESSURE",  "MOTOR",  "T0",     "W0",     "PNEU",    "SERVO",     "KP",
    "KI",    "KD",       "CYL",    "HMOTOR",    "VALVE",  "DP",     "COMP",   "NONE",    "PRE",       "POST",
    "TAU",   "DEAD",     "FRICTION", "P0",      "DISP",   "VOLUME", "BULK",   "LAMINAR", "FLOW",      "MARGIN",
    "POINT", "TORQUE",   "JOINT",  "SPRING",    "AERO",   "P",      "DIR",    "MAG",     "LOCAL",     "SIN",
    "TABLE", "Q",        "K",      "L0",        "AREA",   "CD",     "CL",     "RHO",     "BOX",       "TUBE",
    "SPHERE", "CONE",    "ELLIPSOID", "PRISM",  "MESH",   "SCALE",  "POS",    "AXIS",    "ROT",       "COLOR",
    "MASS",  "MU",       "E",      "NOCONTACT"};

}  // namespace solver::keywords
