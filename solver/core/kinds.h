#pragma once
// The kinds of joint, applied force and force magnitude. The model as written
// (solver/spec/model_spec.h) and the compiled Model (core/model.h) share them, so
// they live here, below every other solver folder.

namespace solver {

enum class JointType {
    Revolute = 0,   ///< T 0 (default): angle about A
    Actuator = 1,   ///< T 1: pivoted linear actuator, revolute about A, coordinate = length CL1–CL2
    Prismatic = 2,  ///< T 2: displacement along R
    /// T 3: a free body (six degrees of freedom). Only in the spec: the compiled Model
    /// expands it into three prismatic and three revolute coordinates (Model::freeSlot).
    Free = 3,
};

/// The coordinates of a free joint (T 3) in the compiled model: three translations, three turns.
inline constexpr int kFreeJointCoordinates = 6;

enum class ForceKind { Point, Torque, Joint, Spring, Aero };

/// A force's magnitude law: a number, `SIN amp freq phase [offset]`, `TABLE T t v …`
/// (a table of time) or `TABLE Q j q v …` (a table of joint j's coordinate).
enum class MagnitudeKind { Constant, Sine, TableTime, TableJoint };

/// A fluid-power valve section's pressure compensator (`COMP NONE|PRE|POST`): none
/// (the orifice law), pre-compensated, or post-compensated (flow sharing).
enum class Compensation { None, Pre, Post };

}  // namespace solver
