#pragma once
// Compiled models for the solver's tests: the example files in models/ and inline
// texts that exercise what those files do not (joints written child → parent, T 1
// and prismatic joints, centres of mass off the frame origin, products of inertia,
// a branching tree, every kind of drive).

#include "solver/core/model.h"
#include "solver/integrate/simulation.h"
#include "solver/pipeline.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace solver::test {

/// Simulation options: classic RK4 at the fixed step h [s].
inline SimulationOptions rk4(double h)
{
    SimulationOptions o;
    o.integrator.method = IntegrationMethod::Rk4Fixed;
    o.integrator.step = h;
    return o;
}

/// Path of an example model in the source tree's models/ folder.
inline std::string modelPath(const std::string& name)
{
    return std::string(PADROB_SOURCE_DIR) + "/models/" + name;
}

/// The compiled model; on any error fails the current test (listing the
/// diagnostics) and returns nullptr.
inline std::shared_ptr<const Model> modelOrFail(const CompiledModel& compiled)
{
    if (!compiled.model) {
        std::string all;
        for (const Diagnostic& d : compiled.diagnostics) all += d.format() + "\n";
        ADD_FAILURE() << "model did not compile:\n" << all;
    }
    return compiled.model;
}

inline std::shared_ptr<const Model> compileText(const std::string& text,
                                                const std::string& file = "<text>")
{
    return modelOrFail(solver::compileText(text, file));
}

/// A file of models/ by name, e.g. "pendulum.pad".
inline std::shared_ptr<const Model> compileExample(const std::string& name)
{
    return modelOrFail(compileFile(modelPath(name)));
}

/// A branching tree of 7 bodies: joint 1 revolute about a tilted axis from the ground;
/// joint 2 revolute and joint 5 T 1 and joint 6 prismatic written child → parent
/// (B1 is the child); joint 3 T 1, joint 4 prismatic along a tilted direction;
/// centres of mass off the frame origins, products of inertia, gravity off the z axis;
/// a motor, two servos, a pneumatic cylinder, two hydraulic cylinders, one passive joint.
/// Tree: 0 ← 1 ← {2 ← 3, 4 ← {5 ← 7, 6}}.
inline const std::string kZooModel = R"pad(GRAVITY 0.4 -0.3 -9.81

B 1 5.0 0.20 0.30 0.25 0.010 -0.020 0.015 CG 0.10 -0.05 0.20 NAME "column"
B 2 3.0 0.10 0.12 0.08 0.005 0.000 -0.010 CG 0.00 0.30 0.05 NAME "arm"
B 3 2.0 0.05 0.06 0.07 CG 0.02 0.01 -0.10 NAME "forearm"
B 4 1.5 0.02 0.03 0.025 0.001 0.002 0.003 NAME "slide"
B 5 4.0 0.30 0.20 0.40 CG -0.10 0.20 0.00 NAME "rocker"
B 6 1.0 0.010 0.012 0.011 0.0005 0 0 CG 0.05 0 0 NAME "tip"
B 7 0.8 0.004 0.005 0.006 NAME "wrist"

C 1 NAME "slew"
B1 0 P1 0.1 0.2 0.5 A1 0 0.2 1 R1 1 0 0
B2 1 P2 0 0 -0.3 A2 0 0 1 R2 1 0 0

C 2 LL -1.0 UL 1.2 NAME "shoulder, written child to parent"
B1 2 P1 0 -0.2 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0.2 0.1 0.3 A2 1 0 0 R2 0 0 1

C 3 T 1 LL 0.30 UL 0.55 NAME "elbow cylinder"
B1 2 P1 0 0.6 0 A1 1 0 0 R1 0 1 0
B2 3 P2 0 -0.3 0 A2 1 0 0 R2 0 1 0
CL1 0 0.2 -0.1 CL2 0 -0.1 -0.08

C 4 T 2 LL -0.2 UL 0.4 QI 0.1 NAME "slide"
B1 1 P1 0.3 0 0.1 A1 0 0 1 R1 1 1 0
B2 4 P2 0 0 0 A2 0 0 1 R2 1 0 0

C 5 T 1 LL 0.40 UL 0.85 NAME "rocker cylinder, written child to parent"
B1 5 P1 0 0 0.1 A1 0 1 0 R1 1 0 0
B2 4 P2 0.1 0 0 A2 0 1 0 R2 1 0 0
CL1 0.3 0 0.2 CL2 -0.5 0 0.1

C 6 T 2 LL -0.3 UL 0.3 NAME "tip slide, written child to parent"
B1 6 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 4 P2 0 0.2 0 A2 1 0 0 R2 0 0 1

C 7 LL -2 UL 2 VI 0.5 NAME "wrist"
B1 5 P1 0.2 0.1 0 A1 0 0 1 R1 1 0 0
B2 7 P2 -0.1 0 0 A2 0 0 1 R2 0 1 0

D 1 MOTOR T0 20 W0 3
D 2 SERVO KP 200 KI 10 KD 5 FMAX 80
D 3 HYD VMAX 0.05 VMIN 0.08 FMAX 5000 FMIN 3000
D 4 PNEU F 30
D 5 HYD VMAX 0.1 FMAX 2000
D 6 SERVO KP 500 KI 0 KD 20
)pad";

/// A serial arm whose T 1 cylinder's length shrinks as its angle grows (dL/dθ < 0),
/// written child → parent in one joint and parent → child in the other, a massless
/// body between two joints, and a prismatic joint at the end; no limits on the
/// second cylinder (its set-point range is the reachable one).
inline const std::string kCylinderArmModel = R"pad(GRAVITY 0 0 -9.81

B 1 NAME "massless yoke"
B 2 20.0 0.5 0.6 0.3 0.02 0.01 -0.03 CG 0.4 0 0.05 NAME "boom"
B 3 8.0 0.1 0.2 0.2 CG 0 0 -0.1 NAME "stick"
B 4 2.0 0.01 0.01 0.01 CG 0 0.05 0 NAME "bucket slide"

C 1 NAME "turntable"
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0

C 2 T 1 LL 0.55 UL 0.75 NAME "boom cylinder"
B1 1 P1 0 0 0.2 A1 0 1 0 R1 1 0 0
B2 2 P2 -0.5 0 0 A2 0 1 0 R2 1 0 0
CL1 -0.4 0 0 CL2 -0.2 0 0.14

C 3 T 1 VI -0.02 NAME "stick cylinder, written child to parent"
B1 3 P1 0 0 0.3 A1 0 1 0 R1 0 0 -1
B2 2 P2 0.5 0 0 A2 0 1 0 R2 1 0 0
CL1 0.1 0 0.2 CL2 0.2 0 0.1

C 4 T 2 LL 0 UL 0.3 QI 0.1 NAME "bucket"
B1 3 P1 0 0 -0.2 A1 1 0 0 R1 0 0 -1
B2 4 P2 0 0 0 A2 1 0 0 R2 0 0 -1

D 1 HYD VMAX 0.3 FMAX 400
D 2 HYD PUMP 20 RPM 1500 BORE 0.08 ROD 0.05 PRESSURE 20e6
D 3 SERVO KP 5000 KI 100 KD 200 FMAX 3000
)pad";

}  // namespace solver::test
