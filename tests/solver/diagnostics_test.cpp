// Every check of the parser and of validateModel, with the exact diagnostic it gives:
// code, severity, line, column and the full text (Diagnostic::format()).
//
// One row per check: a small model with one mistake and the diagnostics expected from
// it, in the order the loader lists them (by position). Models that must pass the
// checks only to reach a warning (not-perpendicular, inertia-triangle) are complete,
// connected models, so the topology analysis runs on them too.

#include "solver/pipeline.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

using namespace solver;

namespace {

/// Body 1 on a revolute joint to ground (lines 1–4); rows append from line 5.
constexpr const char* kRevolute = R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad";

/// Body 1 on a prismatic joint with limits and an initial rate of 0.5 m/s (lines 1–4).
constexpr const char* kPrismatic = R"pad(B 1 1 1 1 1
C 1 T 2 LL 0 UL 1 QI 0.5 VI 0.5
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad";

struct Expected {
    std::string code;
    std::string formatted;  ///< Diagnostic::format(): "m.pad:L:C: severity: message [hint]"
};

struct Case {
    std::string name;
    std::string text;
    std::vector<Expected> expected;  ///< empty: the model loads without any diagnostic
};

std::string listing(const Diagnostics& diags)
{
    std::string s;
    for (const Diagnostic& d : diags) s += "  " + d.code + " | " + d.format() + "\n";
    return s.empty() ? "  (none)\n" : s;
}

/// Compares the diagnostics with the expected ones, in order, and checks that the
/// position and severity fields agree with the formatted text.
void expectDiagnostics(const CompiledModel& m, const std::vector<Expected>& expected)
{
    const auto& items = m.diagnostics.items();
    ASSERT_EQ(items.size(), expected.size()) << "diagnostics:\n" << listing(m.diagnostics);
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const Diagnostic& d = items[k];
        EXPECT_EQ(d.code, expected[k].code) << "diagnostic " << k;
        EXPECT_EQ(d.format(), expected[k].formatted) << "diagnostic " << k;
        EXPECT_EQ(d.file, "m.pad");
        const std::string pos = "m.pad:" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + ": " +
                                severityName(d.severity) + ": ";
        EXPECT_EQ(expected[k].formatted.substr(0, pos.size()), pos) << "diagnostic " << k;
    }
}

const std::vector<Case>& cases()
{
    static const std::vector<Case> table = {
        {"UnknownKeywordWithSuggestion",
         R"pad(GRAVTY 0 0 -9.81
)pad",
         {{"unknown-keyword",
              "m.pad:1:1: error: unknown keyword 'GRAVTY' [did you mean 'GRAVITY'?]"}}},
        {"UnknownKeywordWithoutSuggestion",
         R"pad(BODY 1 10 1 1 1
)pad",
         {{"unknown-keyword",
              "m.pad:1:1: error: unknown keyword 'BODY' [statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C (with B1, B2, CL1), D, F and G; comments start with // or #]"}}},
        {"RestitutionOutOfRange",
         R"pad(RESTITUTION 1.5
)pad",
         {{"bad-restitution",
              "m.pad:1:13: error: RESTITUTION 1.5 is outside 0 … 1 [0 stops a joint dead at its limit, 1 bounces it back at the same speed]"}}},
        {"DuplicateRestitution",
         R"pad(RESTITUTION 0.2
RESTITUTION 0.5
)pad",
         {{"duplicate-restitution",
              "m.pad:2:1: error: RESTITUTION is given twice (first at line 1) [keep one RESTITUTION statement]"}}},
        {"StatementStartsWithNumber",
         R"pad(12 B 1
)pad",
         {{"expected-keyword",
              "m.pad:1:1: error: a statement starts with a keyword, not with the number 12 [start the line with GRAVITY, B, C, D, F or G, or join it to the line above]"}}},
        {"StatementStartsWithString",
         R"pad("x" B 1
)pad",
         {{"expected-keyword",
              "m.pad:1:1: error: a statement cannot start with a string [start the line with GRAVITY, B, C, D, F or G, or join it to the line above]"}}},
        {"BodyMissingNumbers",
         R"pad(B 1 10 1 1
)pad",
         {{"missing-number",
              "m.pad:1:10: error: body 1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found 3 [give the mass and the three moments of inertia: B id [m Ixx Iyy Izz [Ixy Iyz Ixz]] [CG x y z] [NAME \"text\"]]"}}},
        {"BodyIncompleteProducts",
         R"pad(B 1 10 1 1 1 0.1
)pad",
         {{"missing-number",
              "m.pad:1:14: error: body 1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found 5 [give all three products of inertia Ixy Iyz Ixz, or none]"}}},
        {"BodyExtraNumbers",
         R"pad(B 1 10 1 1 1 0 0 0 5
)pad",
         {{"extra-number",
              "m.pad:1:20: error: body 1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found 8 [remove the extra numbers]"}}},
        {"GravityMissingNumber",
         R"pad(GRAVITY 0 0
)pad",
         {{"missing-number",
              "m.pad:1:12: error: GRAVITY: GRAVITY needs 3 numbers, only 2 given [write GRAVITY gx gy gz (m/s², z is up)]"}}},
        {"GravityExtraNumber",
         R"pad(GRAVITY 0 0 -9.81 2
)pad",
         {{"extra-number",
              "m.pad:1:19: error: GRAVITY: unexpected number 2 [remove it]"}}},
        {"JointOptionMissingValue",
         R"pad(B 1 1 1 1 1
C 1 LL
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"missing-number",
              "m.pad:2:7: error: joint 1: the lower limit after LL is missing [write LL the lower limit]"}}},
        {"VectorMissingNumber",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"missing-number",
              "m.pad:3:13: error: joint 1, B1: P1 needs 3 numbers, only 2 given [write P1 x y z]"}}},
        {"ExtraNumberAfterOption",
         R"pad(B 1 1 1 1 1 CG 0 0 0 7
)pad",
         {{"extra-number",
              "m.pad:1:22: error: body 1: unexpected number 7 [remove it, or put an option before it (CG, NAME)]"}}},
        {"UnknownOptionWithSuggestion",
         R"pad(B 1 1 1 1 1
C 1 QUI 0.5
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"unknown-option",
              "m.pad:2:5: error: joint 1: 'QUI' is not an option of a joint statement (C) [did you mean 'QI'?]"}}},
        {"DuplicateOption",
         R"pad(B 1 1 1 1 1 NAME "a" NAME "b"
)pad",
         {{"duplicate-option",
              "m.pad:1:22: error: body 1: NAME is given twice [keep one NAME]"}}},
        {"MalformedNumber",
         R"pad(B 1 10 1.2.3 1 1
)pad",
         {{"not-a-number",
              "m.pad:1:8: error: body 1: '1.2.3' is not a number [numbers look like 12, -0.5, .2 or 1e-3]"}}},
        {"WordInPlaceOfMassNumber",
         R"pad(B 1 10 abc 1 1
)pad",
         {{"not-a-number",
              "m.pad:1:8: error: body 1: 'abc' is not a number [numbers look like 12, -0.5, .2 or 1e-3]"}}},
        {"WordInPlaceOfVectorNumber",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 x 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"not-a-number",
              "m.pad:3:11: error: joint 1, B1: 'x' is not a number [numbers look like 12, -0.5, .2 or 1e-3]"}}},
        {"WordInPlaceOfBodyId",
         R"pad(B 1 1 1 1 1
C 1
B1 base P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"missing-id",
              "m.pad:3:4: error: joint 1, B1: the body id is missing, found 'base' [write B1 body P1 x y z A1 x y z R1 x y z]"}}},
        {"DecimalComma",
         R"pad(B 1 10 1 1 4,5
)pad",
         {{"decimal-comma",
              "m.pad:1:12: error: body 1: '4,5' is not a number [use '.' as the decimal separator: 4.5]"}}},
        {"DecimalCommaInVector",
         R"pad(GRAVITY 0 0 -9,81
)pad",
         {{"decimal-comma",
              "m.pad:1:13: error: GRAVITY: '-9,81' is not a number [use '.' as the decimal separator: -9.81]"}}},
        {"NotFiniteNaN",
         R"pad(B 1 nan 1 1 1
)pad",
         {{"not-finite",
              "m.pad:1:5: error: body 1: 'nan' is not a finite number [write a finite value; NaN and infinity are not allowed]"}}},
        {"NotFiniteInf",
         R"pad(GRAVITY 0 0 -Inf
)pad",
         {{"not-finite",
              "m.pad:1:13: error: GRAVITY: '-Inf' is not a finite number [write a finite value; NaN and infinity are not allowed]"}}},
        {"NumberOutOfRange",
         R"pad(B 1 10 1 1 1e999
)pad",
         {{"number-out-of-range",
              "m.pad:1:12: error: body 1: 1e999 is out of range [a number must lie within ±1.7e308]"}}},
        {"NegativeId",
         R"pad(B -1
)pad",
         {{"bad-id",
              "m.pad:1:3: error: body: the body id cannot be negative (-1) [ids are whole numbers 0, 1, 2, …]"}}},
        {"FractionalId",
         R"pad(B 1.5
)pad",
         {{"bad-id",
              "m.pad:1:3: error: body: the body id must be a whole number, not 1.5 [ids are whole numbers 0, 1, 2, …]"}}},
        {"IdAboveIntMax",
         R"pad(B 2147483648
)pad",
         {{"bad-id",
              "m.pad:1:3: error: body: the body id 2147483648 is too large [ids go from 0 to 2147483647]"}}},
        {"IdFarAboveIntMax",
         R"pad(F 99999999999999999999999 JOINT 1 MAG 1
)pad",
         {{"bad-id",
              "m.pad:1:3: error: force: the force id 99999999999999999999999 is too large [ids go from 0 to 2147483647]"}}},
        {"MissingId",
         R"pad(C
)pad",
         {{"missing-id",
              "m.pad:1:2: error: joint: the joint id is missing [write C id [T 0|1|2|3] [LL v] [UL v] [QI v] [VI v] [NAME \"text\"]]"}}},
        {"DuplicateBodyId",
         R"pad(B 1 1 1 1 1
B 1 2 2 2 2
)pad",
         {{"duplicate-id",
              "m.pad:2:1: error: body 1 is defined twice (first at line 1) [give it another id or remove one of the two]"}}},
        {"DuplicateJointId",
         R"pad(B 1 1 1 1 1
B 2 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 1
B1 1 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 2 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"duplicate-id",
              "m.pad:6:1: error: joint 1 is defined twice (first at line 3) [give it another id or remove one of the two]"}}},
        {"DuplicateForceId",
         std::string(kRevolute) + R"pad(F 4 JOINT 1 MAG 1
F 4 JOINT 1 MAG 2
)pad",
         {{"duplicate-id",
              "m.pad:6:1: error: force 4 is defined twice (first at line 5) [give it another id or remove one of the two]"}}},
        {"DuplicateGraphicId",
         std::string(kRevolute) + R"pad(G 3 B 1 SPHERE 0.1
G 3 B 1 SPHERE 0.2
)pad",
         {{"duplicate-id",
              "m.pad:6:1: error: graphic 3 is defined twice (first at line 5) [give it another id or remove one of the two]"}}},
        {"DuplicateGravity",
         R"pad(GRAVITY 0 0 -9.81
GRAVITY 0 0 -1.62
)pad",
         {{"duplicate-gravity",
              "m.pad:2:1: error: GRAVITY is given twice (first at line 1) [keep one GRAVITY statement]"}}},
        {"JointUndefinedBody",
         R"pad(C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 3 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"undefined-body",
              "m.pad:3:4: error: joint 1: body 3 (B2) is not defined [add 'B 3 m Ixx Iyy Izz', or use an existing body]"}}},
        {"JointSameBodyTwice",
         R"pad(B 1 1 1 1 1
C 1
B1 1 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"same-body",
              "m.pad:4:4: error: joint 1 connects body 1 to itself [B1 and B2 must name two different bodies]"}}},
        {"JointWithoutB1",
         R"pad(B 1 1 1 1 1
C 1
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"missing-joint-line",
              "m.pad:2:1: error: joint 1 has no B1 line [follow the C line with B1 body P1 x y z A1 x y z R1 x y z]"}}},
        {"JointWithoutB2",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
)pad",
         {{"missing-joint-line",
              "m.pad:2:1: error: joint 1 has no B2 line [follow the C line with B2 body P2 x y z A2 x y z R2 x y z]"}}},
        {"B1OutsideJoint",
         R"pad(B 1 1 1 1 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
)pad",
         {{"orphan-joint-line",
              "m.pad:2:1: error: B1 must follow a joint statement (C) [put it right after its joint's C line (blank and comment lines may come between)]"}}},
        {"DuplicateB1",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"duplicate-joint-line",
              "m.pad:4:1: error: joint 1 already has a B1 line (line 3) [keep one B1 line per joint]"}}},
        {"WrongSideKey",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P2 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"wrong-side",
              "m.pad:3:6: error: joint 1, B1: P2 belongs on the B2 line [on the B1 line write P1]"}}},
        {"ClMissingOnActuator",
         R"pad(B 1 1 1 1 1
C 1 T 1 LL 1 UL 2
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"missing-cl",
              "m.pad:2:1: error: joint 1 is a pivoted linear actuator (T 1) but has no CL1/CL2 line [add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in their local frames]"}}},
        {"Cl2MissingOnActuator",
         R"pad(B 1 1 1 1 1
C 1 T 1 LL 1 UL 2
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
CL1 0 0 1
)pad",
         {{"missing-cl",
              "m.pad:2:1: error: joint 1 is a pivoted linear actuator (T 1) but has no CL2 [add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in their local frames]"}}},
        {"ClOnRevolute",
         R"pad(B 1 1 1 1 1
C 1 T 0
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
CL1 0 0 0 CL2 0 1 0
)pad",
         {{"unexpected-cl",
              "m.pad:5:5: error: joint 1 has CL1/CL2 but is not a pivoted linear actuator [CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line]"}}},
        {"ClOnPrismatic",
         R"pad(B 1 1 1 1 1
C 1 T 2
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
CL1 0 0 0 CL2 0 1 0
)pad",
         {{"unexpected-cl",
              "m.pad:5:5: error: joint 1 has CL1/CL2 but is not a pivoted linear actuator [CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line]"}}},
        {"BadJointType",
         R"pad(B 1 1 1 1 1
C 1 T 4
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"bad-joint-type",
              "m.pad:2:7: error: joint 1: there is no joint type T 4 [use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 (prismatic) or T 3 (free body)]"}}},
        {"NegativeJointType",
         R"pad(B 1 1 1 1 1
C 1 T -1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"bad-joint-type",
              "m.pad:2:7: error: joint 1: there is no joint type T -1 [use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 (prismatic) or T 3 (free body)]"}}},
        {"DegOnPrismaticLength",
         R"pad(B 1 1 1 1 1
C 1 T 2 LL 5 DEG
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"deg-on-length",
              "m.pad:2:12: error: joint 1: DEG after LL, but the coordinate of a prismatic joint (T 2) is a length [remove DEG; give the value in metres]"}}},
        {"AxisAndReferenceOfZeroLength",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 0 0
)pad",
         {{"zero-vector",
              "m.pad:3:18: error: joint 1: A1 has zero length [the axis is a direction, e.g. A1 0 0 1]"},
             {"zero-vector",
              "m.pad:4:27: error: joint 1: R2 has zero length [the reference direction is a direction perpendicular to A2, e.g. R2 0 1 0]"}}},
        {"AxisParallelToReference",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 0 -2
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"axis-parallel",
              "m.pad:3:27: error: joint 1: R1 is parallel to A1 [R1 must be perpendicular to the axis A1]"}}},
        {"NotPerpendicularWarning",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0.0000011
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"not-perpendicular",
              "m.pad:3:27: warning: joint 1: R1 is not perpendicular to A1 (angle 89.9999°); R1 is made perpendicular [write R1 at 90° to A1]"}}},
        {"AlmostPerpendicularNoWarning",
         R"pad(B 1 1 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0.0000009
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {}},
        {"LimitsReversed",
         R"pad(B 1 1 1 1 1
C 1 LL 1 UL -1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"limits-reversed",
              "m.pad:2:8: error: joint 1: the lower limit LL = 1 rad is above the upper limit UL = -1 rad [swap LL and UL]"}}},
        {"QiAboveUpperLimit",
         R"pad(B 1 1 1 1 1
C 1 LL -1 UL 1 QI 2
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"qi-outside-limits",
              "m.pad:2:19: error: joint 1: QI = 2 rad is above the upper limit UL = 1 rad [give QI between LL and UL]"}}},
        {"QiBelowLowerLimitInDegrees",
         R"pad(B 1 1 1 1 1
C 1 LL -90 DEG UL 90 DEG QI -100 DEG
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"qi-outside-limits",
              "m.pad:2:29: error: joint 1: QI = -1.74533 rad is below the lower limit LL = -1.5708 rad [give QI between LL and UL]"}}},
        {"ViPastUpperLimit",
         R"pad(B 1 1 1 1 1
C 1 LL -1 UL 1 QI 1 VI 0.5
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"vi-outside-limits",
              "m.pad:2:24: error: joint 1: VI = 0.5 moves the joint past its upper limit UL = 1 rad, where it starts [start it inside its limits, or give VI ≤ 0]"}}},
        {"ViPastLowerLimit",
         R"pad(B 1 1 1 1 1
C 1 T 2 LL 0 UL 1 VI -0.1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"vi-outside-limits",
              "m.pad:2:22: error: joint 1: VI = -0.1 moves the joint past its lower limit LL = 0 m, where it starts [start it inside its limits, or give VI ≥ 0]"}}},
        {"ViAboveHydraulicVmax",
         std::string(kPrismatic) + R"pad(D 1 HYD VMAX 0.2
)pad",
         {{"vi-above-vmax",
              "m.pad:2:29: error: joint 1: VI = 0.5 is faster than its hydraulic drive can move it (0.2) [give |VI| ≤ VMAX (extending) or VMIN (retracting)]"}}},
        {"ViBelowHydraulicVmin",
         R"pad(B 1 1 1 1 1
C 1 T 2 LL 0 UL 1 QI 0.5 VI -0.3
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
D 1 HYD VMAX 0.5 VMIN 0.25
)pad",
         {{"vi-above-vmax",
              "m.pad:2:29: error: joint 1: VI = -0.3 is faster than its hydraulic drive can move it (0.25) [give |VI| ≤ VMAX (extending) or VMIN (retracting)]"}}},
        {"NegativeMass",
         R"pad(B 1 -5 1 1 1
)pad",
         {{"negative-mass",
              "m.pad:1:5: error: body 1 has a negative mass (-5 kg) [a mass is zero or positive, in kg]"}}},
        {"GroundWithMass",
         R"pad(B 0 5 1 1 1
)pad",
         {{"ground-mass",
              "m.pad:1:5: error: body 0 is the ground and cannot have a mass or inertia [remove the numbers from 'B 0', or give the body another id]"}}},
        {"InertiaNotPositiveSemiDefinite",
         R"pad(B 1 5 1 -1 1
)pad",
         {{"inertia-not-psd",
              "m.pad:1:7: error: body 1's inertia tensor is not positive semi-definite (principal moments -1, 1, 1 kg m²) [moments of inertia are zero or positive, and products of inertia cannot outweigh them; check signs and units (kg m²)]"}}},
        {"InertiaNotPsdViaProducts",
         R"pad(B 1 5 1 1 1 2 0 0
)pad",
         {{"inertia-not-psd",
              "m.pad:1:7: error: body 1's inertia tensor is not positive semi-definite (principal moments -1, 1, 3 kg m²) [moments of inertia are zero or positive, and products of inertia cannot outweigh them; check signs and units (kg m²)]"}}},
        {"InertiaTriangleWarning",
         R"pad(B 1 5 1 1 3
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"inertia-triangle",
              "m.pad:1:7: warning: body 1's principal moments of inertia 1, 1, 3 kg m² break the triangle inequality (1 + 1 < 3): no real body has them [check the values; the inertia calculator computes them from the body's shapes]"}}},
        {"InertiaTriangleWarningViaProducts",
         R"pad(B 1 5 2 2 2 0 0 1.5
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"inertia-triangle",
              "m.pad:1:7: warning: body 1's principal moments of inertia 0.5, 2, 3.5 kg m² break the triangle inequality (0.5 + 2 < 3.5): no real body has them [check the values; the inertia calculator computes them from the body's shapes]"}}},
        {"DriveOnUndefinedJoint",
         std::string(kRevolute) + R"pad(D 7 HYD VMAX 1
)pad",
         {{"undefined-joint",
              "m.pad:5:1: error: drive on joint 7: joint 7 is not defined [use the id of a joint (C id …)]"}}},
        {"TwoDrivesOnOneJoint",
         std::string(kRevolute) + R"pad(D 1 HYD VMAX 1
D 1 MOTOR T0 1 W0 1
)pad",
         {{"duplicate-drive",
              "m.pad:6:1: error: joint 1 already has a drive (line 5) [one joint takes one drive; remove one of them]"}}},
        {"UnknownDriveKindWithSuggestion",
         std::string(kRevolute) + R"pad(D 1 HDY VMAX 1
)pad",
         {{"unknown-drive-kind",
              "m.pad:5:5: error: drive on joint 1: unknown drive kind 'HDY' [did you mean 'HYD'?]"}}},
        {"UnknownDriveKind",
         std::string(kRevolute) + R"pad(D 1 ELECTRIC T0 1
)pad",
         {{"unknown-drive-kind",
              "m.pad:5:5: error: drive on joint 1: unknown drive kind 'ELECTRIC' [drive kinds are HYD, MOTOR, PNEU, SERVO, CYL and HMOTOR]"}}},
        {"HydraulicVmaxAndPump",
         std::string(kPrismatic) + R"pad(D 1 HYD VMAX 1 PUMP 10 RPM 1000 BORE 0.1 ROD 0.05 PRESSURE 2e7
)pad",
         {{"hyd-conflict",
              "m.pad:5:21: error: drive on joint 1: give either VMAX/FMAX or the hydraulic data PUMP … PRESSURE, not both [remove one of the two forms]"}}},
        {"HydraulicWithoutVmax",
         std::string(kPrismatic) + R"pad(D 1 HYD FMAX 1000
)pad",
         {{"missing-option",
              "m.pad:5:1: error: drive on joint 1: a hydraulic drive needs VMAX or the pump data [write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa]"}}},
        {"HydraulicPumpIncomplete",
         std::string(kPrismatic) + R"pad(D 1 HYD PUMP 10 RPM 1000 BORE 0.1
)pad",
         {{"missing-option",
              "m.pad:5:1: error: drive on joint 1: ROD is missing [write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa]"},
             {"missing-option",
              "m.pad:5:1: error: drive on joint 1: PRESSURE is missing [write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa]"}}},
        {"MotorMissingW0",
         std::string(kRevolute) + R"pad(D 1 MOTOR T0 5
)pad",
         {{"missing-option",
              "m.pad:5:1: error: drive on joint 1: W0 is missing [write D j MOTOR T0 torque W0 speed]"}}},
        {"ServoMissingGains",
         std::string(kRevolute) + R"pad(D 1 SERVO KP 1
)pad",
         {{"missing-option",
              "m.pad:5:1: error: drive on joint 1: KI is missing [write D j SERVO KP p KI i KD d [FMAX f]]"},
             {"missing-option",
              "m.pad:5:1: error: drive on joint 1: KD is missing [write D j SERVO KP p KI i KD d [FMAX f]]"}}},
        {"PneumaticMissingForce",
         std::string(kPrismatic) + R"pad(D 1 PNEU
)pad",
         {{"missing-option",
              "m.pad:5:1: error: drive on joint 1: F is missing [write D j PNEU F force]"}}},
        {"VmaxZero",
         std::string(kPrismatic) + R"pad(D 1 HYD VMAX 0
)pad",
         {{"not-positive",
              "m.pad:5:14: error: drive on joint 1: VMAX must be positive, not 0 [give its magnitude; the direction comes from the operator's command]"}}},
        {"VmaxNegative",
         std::string(kPrismatic) + R"pad(D 1 HYD VMAX -1
)pad",
         {{"not-positive",
              "m.pad:5:14: error: drive on joint 1: VMAX must be positive, not -1 [give its magnitude; the direction comes from the operator's command]"}}},
        {"RodNotThinnerThanBore",
         std::string(kPrismatic) + R"pad(D 1 HYD PUMP 10 RPM 1000 BORE 0.1 ROD 0.1 PRESSURE 2e7
)pad",
         {{"rod-too-large",
              "m.pad:5:39: error: drive on joint 1: the rod (0.1 m) is not thinner than the bore (0.1 m) [ROD and BORE are diameters in metres; the rod must be thinner]"}}},
        {"PumpOnRevolute",
         std::string(kRevolute) + R"pad(D 1 HYD PUMP 10 RPM 1000 BORE 0.1 ROD 0.05 PRESSURE 2e7
)pad",
         {{"pump-on-revolute",
              "m.pad:5:14: error: drive on joint 1: PUMP/BORE/ROD describe a cylinder, but joint 1 is revolute [for a hydraulic motor give VMAX (rad/s) and FMAX (N·m); or make the joint T 1 or T 2]"}}},
        {"PointForceOnUndefinedBody",
         std::string(kRevolute) + R"pad(F 1 POINT B 5 P 0 0 0 DIR 0 0 1 MAG 10
)pad",
         {{"undefined-body",
              "m.pad:5:13: error: force 1: body 5 is not defined [use the id of a body (B id …)]"}}},
        {"SpringToUndefinedBody",
         std::string(kRevolute) + R"pad(F 1 SPRING B1 0 P1 0 0 0 B2 9 P2 0 0 0 K 100 L0 1
)pad",
         {{"undefined-body",
              "m.pad:5:29: error: force 1: body 9 is not defined [use the id of a body (B id …)]"}}},
        {"JointForceOnUndefinedJoint",
         std::string(kRevolute) + R"pad(F 1 JOINT 5 MAG 10
)pad",
         {{"undefined-joint",
              "m.pad:5:11: error: force 1: joint 5 is not defined [use the id of a joint (C id …)]"}}},
        {"TableQOnUndefinedJoint",
         std::string(kRevolute) + R"pad(F 1 TORQUE B 1 DIR 0 0 1 MAG TABLE Q 3 0 1 1 2
)pad",
         {{"undefined-joint",
              "m.pad:5:38: error: force 1: joint 3 is not defined [use the id of a joint (C id …)]"}}},
        {"PointForceZeroDir",
         std::string(kRevolute) + R"pad(F 1 POINT B 1 P 0 0 0 DIR 0 0 0 MAG 10
)pad",
         {{"zero-vector",
              "m.pad:5:27: error: force 1: DIR has zero length [give the force's direction, e.g. DIR 0 0 -1]"}}},
        {"TorqueZeroDir",
         std::string(kRevolute) + R"pad(F 1 TORQUE B 1 DIR 0 0 0 MAG 10
)pad",
         {{"zero-vector",
              "m.pad:5:20: error: force 1: DIR has zero length [give the force's direction, e.g. DIR 0 0 -1]"}}},
        {"TableNotIncreasing",
         std::string(kRevolute) + R"pad(F 1 JOINT 1 MAG TABLE T 0 1 0 2
)pad",
         {{"table-not-increasing",
              "m.pad:5:29: error: force 1: table abscissae must increase (0 follows 0) [sort the pairs by their first number and remove repeats]"}}},
        {"TableOdd",
         std::string(kRevolute) + R"pad(F 1 JOINT 1 MAG TABLE T 0 1 1
)pad",
         {{"bad-table",
              "m.pad:5:29: error: force 1: a TABLE needs pairs of numbers (abscissa value), found 3 numbers [write TABLE T t1 v1 t2 v2 …]"}}},
        {"TableWithoutTOrQ",
         std::string(kRevolute) + R"pad(F 1 JOINT 1 MAG TABLE X 0 1 1 2
)pad",
         {{"bad-table",
              "m.pad:5:23: error: force 1: TABLE must say T (by time) or Q (by a joint's coordinate) [write TABLE T t1 v1 t2 v2 … or TABLE Q joint q1 v1 q2 v2 …]"}}},
        {"SineMissingNumber",
         std::string(kRevolute) + R"pad(F 1 JOINT 1 MAG SIN 1 2
)pad",
         {{"missing-number",
              "m.pad:5:24: error: force 1: SIN needs 3 numbers, only 2 given [write SIN amplitude frequency[Hz] phase[rad] [offset]]"}}},
        {"MagnitudeMissing",
         std::string(kRevolute) + R"pad(F 1 JOINT 1 MAG
)pad",
         {{"missing-number",
              "m.pad:5:16: error: force 1: MAG needs a value [write MAG value, MAG SIN amp freq phase [offset], MAG TABLE T t1 v1 t2 v2 … or MAG TABLE Q joint q1 v1 …]"}}},
        {"UnknownForceKind",
         std::string(kRevolute) + R"pad(F 1 PUSH B 1
)pad",
         {{"unknown-force-kind",
              "m.pad:5:5: error: force 1: unknown force kind 'PUSH' [force kinds are POINT, TORQUE, JOINT, SPRING and AERO]"}}},
        {"ForceMissingOption",
         std::string(kRevolute) + R"pad(F 1 SPRING B1 0 P1 0 0 0 B2 1 P2 0 0 0 L0 1
)pad",
         {{"missing-option",
              "m.pad:5:1: error: force 1: K is missing [write F id SPRING B1 i P1 x y z B2 k P2 x y z K k L0 l [C c]]"}}},
        {"UnknownShapeWithSuggestion",
         std::string(kRevolute) + R"pad(G 1 B 1 BOKS 1 2 3
)pad",
         {{"unknown-shape",
              "m.pad:5:9: error: graphic 1: unknown shape 'BOKS' [did you mean 'BOX'?]"}}},
        {"UnknownShape",
         std::string(kRevolute) + R"pad(G 1 B 1 PYRAMID 1 2 3
)pad",
         {{"unknown-shape",
              "m.pad:5:9: error: graphic 1: unknown shape 'PYRAMID' [shapes are BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM and MESH]"}}},
        {"ShapeDimensionZero",
         std::string(kRevolute) + R"pad(G 1 B 1 BOX 1 0 3
)pad",
         {{"not-positive",
              "m.pad:5:13: error: graphic 1: BOX dimension 2 must be positive, not 0 [dimensions are lengths in metres]"}}},
        {"ShapeDimensionNegative",
         std::string(kRevolute) + R"pad(G 1 B 1 CYL -1 3
)pad",
         {{"not-positive",
              "m.pad:5:13: error: graphic 1: CYL dimension 1 must be positive, not -1 [dimensions are lengths in metres]"}}},
        {"ShapeDimensionMissing",
         std::string(kRevolute) + R"pad(G 1 B 1 CONE 0.1
)pad",
         {{"missing-number",
              "m.pad:5:17: error: graphic 1: CONE dimension 2 of 2 (R L) is missing [write CONE R L]"}}},
        {"TubeInnerNotSmaller",
         std::string(kRevolute) + R"pad(G 1 B 1 TUBE 0.1 0.2 1
)pad",
         {{"tube-radii",
              "m.pad:5:14: error: graphic 1: the TUBE's inner radius is not smaller than its outer radius [write TUBE RO RI L with RI < RO]"}}},
        {"PrismTooFewVertices",
         std::string(kRevolute) + R"pad(G 1 B 1 PRISM 0.1 0 0 1 0
)pad",
         {{"bad-prism",
              "m.pad:5:15: error: graphic 1: PRISM needs its height H and at least three x y vertices, found 5 numbers [write PRISM H x1 y1 x2 y2 x3 y3 …]"}}},
        {"PrismWithoutArea",
         std::string(kRevolute) + R"pad(G 1 B 1 PRISM 0.1 0 0 1 0 2 0
)pad",
         {{"bad-prism",
              "m.pad:5:15: error: graphic 1: the PRISM's outline has no area [give at least three x y vertices that are not on one line]"}}},
        {"ColorOutOfRange",
         std::string(kRevolute) + R"pad(G 1 B 1 BOX 1 1 1 COLOR 1.5 0 0
)pad",
         {{"bad-color",
              "m.pad:5:25: error: graphic 1: COLOR components must lie between 0 and 1 [write COLOR r g b with 0 ≤ r, g, b ≤ 1 (e.g. 0.8 0.1 0.1 for red)]"}}},
        {"MassAndRho",
         std::string(kRevolute) + R"pad(G 1 B 1 BOX 1 1 1 MASS 1 RHO 7850
)pad",
         {{"mass-and-rho",
              "m.pad:5:30: error: graphic 1: give MASS or RHO, not both [MASS is the solid's mass in kg; RHO its density in kg/m³]"}}},
        {"MeshFileNotFound",
         std::string(kRevolute) + R"pad(G 1 B 1 MESH "nothere.stl"
)pad",
         {{"mesh-not-found",
              "m.pad:5:14: error: graphic 1: mesh file 'nothere.stl' not found (looked for ./nothere.stl) [mesh paths are relative to the model file's folder]"}}},
        {"MeshFileNameWithoutQuotes",
         std::string(kRevolute) + R"pad(G 1 B 1 MESH nothere.stl SCALE 0.001
)pad",
         {{"missing-string",
              "m.pad:5:14: error: graphic 1: the MESH file name must be in double quotes [write MESH \"nothere.stl\"]"}}},
        {"GraphicOnUndefinedBody",
         std::string(kRevolute) + R"pad(G 1 B 7 BOX 1 1 1
)pad",
         {{"undefined-body",
              "m.pad:5:7: error: graphic 1: body 7 is not defined [use the id of a body (B id …), or 0 for the ground]"}}},
        {"UnterminatedString",
         R"pad(B 1 1 1 1 1 NAME "open
)pad",
         {{"unterminated-string",
              "m.pad:1:18: error: the string has no closing quote [add '\"' at the end of the text]"}}},
        {"ControlCharacter",
         "B 1 1 1 1 1 \x07\n",
         {{"control-character",
              "m.pad:1:13: error: unexpected control character (code 7) [delete it; a model file is plain text]"}}},
        {"ControlCharacterInString",
         "B 1 1 1 1 1 NAME \"a\x01" "b\"\n",  // a control character inside a name
         {{"control-character",
              "m.pad:1:20: error: unexpected control character (code 1) [delete it; a model file is plain text]"}}},
        {"NameWithoutQuotes",
         R"pad(B 1 1 1 1 1 NAME GIRO PLUMA
)pad",
         {{"missing-string",
              "m.pad:1:18: error: body 1: NAME needs a text in double quotes [write NAME \"GIRO PLUMA\"]"}}},
        {"NameWithoutText",
         R"pad(B 1 1 1 1 1 NAME
)pad",
         {{"missing-string",
              "m.pad:1:17: error: body 1: NAME needs a text in double quotes [write NAME \"text\"]"}}},
        {"DriveKindMissing",
         std::string(kRevolute) + R"pad(D 1
)pad",
         {{"missing-drive-kind",
              "m.pad:5:4: error: drive on joint 1: the drive kind is missing [write HYD, MOTOR, PNEU, SERVO, CYL or HMOTOR after the joint id]"}}},
        {"ForceKindMissing",
         std::string(kRevolute) + R"pad(F 2
)pad",
         {{"missing-force-kind",
              "m.pad:5:4: error: force 2: the force kind is missing [write POINT, TORQUE, JOINT, SPRING or AERO after the force id]"}}},
        {"ShapeMissing",
         std::string(kRevolute) + R"pad(G 1 B 1
)pad",
         {{"missing-shape",
              "m.pad:5:8: error: graphic 1: the shape is missing [write BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH and its dimensions]"}}},
        {"GraphicWithoutBody",
         std::string(kRevolute) + R"pad(G 1 BOX 1 1 1
)pad",
         {{"missing-option",
              "m.pad:5:5: error: graphic 1: B body is missing after the id [write G id B body SHAPE dimensions… [POS x y z] [AXIS x y z] [ROT ax ay az deg] [COLOR r g b] [MASS m | RHO density]]"}}},
        {"InertiaWithoutMassWarning",
         R"pad(B 1 0 1 1 1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
         {{"inertia-without-mass",
              "m.pad:1:5: warning: body 1 has no mass but a non-zero inertia [give its mass, or set the inertia to zero as well]"}}},
        {"ActuatorLimitNotALength",
         R"pad(B 1 1 1 1 1
C 1 T 1 LL 0 UL 2
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
CL1 0 0 1 CL2 0 1 0
)pad",
         {{"bad-length",
              "m.pad:2:12: error: joint 1: LL = 0 m, but a T 1 joint's coordinate is the actuator's length [give the cylinder's length between CL1 and CL2, in metres (positive)]"}}},
        {"ActuatorQiNotALength",
         R"pad(B 1 1 1 1 1
C 1 T 1 QI -1
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
CL1 0 0 1 CL2 0 1 0
)pad",
         {{"bad-length",
              "m.pad:2:12: error: joint 1: QI = -1 m, but a T 1 joint's coordinate is the actuator's length [give the cylinder's initial length between CL1 and CL2, in metres (positive)]"}}},
        {"DegOnActuatorLength",
         R"pad(B 1 1 1 1 1
C 1 T 1 QI 1.5 DEG
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
CL1 0 0 1 CL2 0 1 0
)pad",
         {{"deg-on-length",
              "m.pad:2:12: error: joint 1: DEG after QI, but the coordinate of a pivoted linear actuator (T 1) is a length [remove DEG; give the value in metres]"}}},
        {"ClGivenTwice",
         R"pad(B 1 1 1 1 1
C 1 T 1 LL 1 UL 2
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
CL1 0 0 1 CL2 0 1 0
CL1 0 0 2
)pad",
         {{"duplicate-joint-line",
              "m.pad:6:1: error: joint 1: CL1 is given twice [keep one CL1]"}}},
        {"ViAbovePumpSpeed",
         std::string(kPrismatic) + R"pad(D 1 HYD PUMP 10 RPM 1000 BORE 0.1 ROD 0.05 PRESSURE 2e7
)pad",
         {{"vi-above-vmax",
              "m.pad:2:29: error: joint 1: VI = 0.5 is faster than its hydraulic drive can move it (0.0212207, from its pump and cylinder data) [give |VI| ≤ flow / bore area (extending) or flow / annulus area (retracting)]"}}},
        {"PumpDataWithVmin",
         std::string(kPrismatic) + R"pad(D 1 HYD PUMP 10 RPM 1000 BORE 0.1 ROD 0.05 PRESSURE 2e7 VMIN 0.1
)pad",
         {{"hyd-conflict",
              "m.pad:5:62: error: drive on joint 1: VMIN follows from the hydraulic data PUMP … PRESSURE [remove VMIN, or give VMAX/VMIN/FMAX/FMIN instead of the pump data]"}}},
        {"ServoNegativeGain",
         std::string(kRevolute) + R"pad(D 1 SERVO KP -1 KI 0 KD 0
)pad",
         {{"not-positive",
              "m.pad:5:14: error: drive on joint 1: KP cannot be negative (-1) [gains are zero or positive]"}}},
        {"SpringOnOneBody",
         std::string(kRevolute) + R"pad(F 1 SPRING B1 1 P1 0 0 0 B2 1 P2 0 1 0 K 100 L0 1
)pad",
         {{"same-body",
              "m.pad:5:29: error: force 1: the spring connects body 1 to itself [B1 and B2 must name two different bodies]"}}},
        {"SpringNegativeValues",
         std::string(kRevolute) + R"pad(F 1 SPRING B1 0 P1 0 0 0 B2 1 P2 0 0 0 K -100 L0 -1 C -2
)pad",
         {{"negative-value",
              "m.pad:5:42: error: force 1: K is negative [a stiffness is ≥ 0, in N/m]"},
             {"negative-value",
              "m.pad:5:50: error: force 1: L0 is negative [a rest length is ≥ 0, in m]"},
             {"negative-value",
              "m.pad:5:55: error: force 1: C is negative [a damping is ≥ 0, in N s/m]"}}},
        {"AeroBadValues",
         std::string(kRevolute) + R"pad(F 2 AERO B 1 P 0 0 0 AREA 0 CD -1 RHO 0
)pad",
         {{"not-positive",
              "m.pad:5:27: error: force 2: AREA must be positive [the reference area in m²]"},
             {"negative-value",
              "m.pad:5:32: error: force 2: CD is negative [a drag coefficient is ≥ 0]"},
             {"not-positive",
              "m.pad:5:39: error: force 2: RHO must be positive [the fluid's density in kg/m³ (air: 1.225)]"}}},
        {"PrismHeightNotPositive",
         std::string(kRevolute) + R"pad(G 1 B 1 PRISM 0 0 0 1 0 0 1
)pad",
         {{"not-positive",
              "m.pad:5:15: error: graphic 1: the PRISM's height H must be positive [H is in metres]"}}},
        {"MeshScaleNotPositive",
         std::string(kRevolute) + R"pad(G 2 B 1 MESH "x.stl" SCALE 0
)pad",
         {{"mesh-not-found",
              "m.pad:5:14: error: graphic 2: mesh file 'x.stl' not found (looked for ./x.stl) [mesh paths are relative to the model file's folder]"},
             {"not-positive",
              "m.pad:5:28: error: graphic 2: SCALE must be positive [SCALE 0.001 turns millimetres into metres]"}}},
        {"GraphicRhoNotPositive",
         std::string(kRevolute) + R"pad(G 3 B 1 BOX 1 1 1 RHO -5
)pad",
         {{"not-positive",
              "m.pad:5:23: error: graphic 3: RHO must be positive [a density in kg/m³ (steel: 7850)]"}}},
        {"GraphicMassNegative",
         std::string(kRevolute) + R"pad(G 4 B 1 BOX 1 1 1 MASS -2
)pad",
         {{"negative-mass",
              "m.pad:5:24: error: graphic 4: MASS is negative [a mass is ≥ 0, in kg]"}}},
        {"GraphicAxesOfZeroLength",
         std::string(kRevolute) + R"pad(G 5 B 1 BOX 1 1 1 AXIS 0 0 0 ROT 0 0 0 30
)pad",
         {{"zero-vector",
              "m.pad:5:24: error: graphic 5: AXIS has zero length [give a direction, e.g. AXIS 1 0 0]"},
             {"zero-vector",
              "m.pad:5:34: error: graphic 5: the ROT axis has zero length [write ROT ax ay az degrees, e.g. ROT 0 0 1 90]"}}},
    };
    return table;
}

class DiagnosticsTable : public testing::TestWithParam<Case> {};

TEST_P(DiagnosticsTable, ExactDiagnostics)
{
    const Case& c = GetParam();
    CompiledModel m = compileText(c.text, "m.pad");
    expectDiagnostics(m, c.expected);
    bool anyError = false;
    for (const Diagnostic& d : m.diagnostics) anyError = anyError || d.severity == Severity::Error;
    EXPECT_EQ(m.ok(), !anyError);
    // a model with errors is never half-loaded; a model without them is analysed
    EXPECT_EQ(m.topology.has_value(), !anyError);
}

INSTANTIATE_TEST_SUITE_P(Check, DiagnosticsTable, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(Diagnostics, IdOfIntMaxIsReadExactly)
{
    CompiledModel m = compileText(R"pad(B 2147483647 2 1 1 1
C 2147483647
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 2147483647 P2 0 0 0 A2 0 0 1 R2 0 1 0
F 2147483647 JOINT 2147483647 MAG 1
G 2147483647 B 2147483647 SPHERE 0.1
)pad",
                                  "m.pad");
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    ASSERT_EQ(m.spec.bodies.size(), 1u);
    EXPECT_EQ(m.spec.bodies[0].id, INT_MAX);
    EXPECT_EQ(m.spec.bodies[0].mass, 2.0);
    ASSERT_EQ(m.spec.joints.size(), 1u);
    EXPECT_EQ(m.spec.joints[0].id, INT_MAX);
    EXPECT_EQ(m.spec.joints[0].side2.body, INT_MAX);
    ASSERT_EQ(m.spec.forces.size(), 1u);
    EXPECT_EQ(m.spec.forces[0].id, INT_MAX);
    EXPECT_EQ(m.spec.forces[0].joint, INT_MAX);
    ASSERT_EQ(m.spec.graphics.size(), 1u);
    EXPECT_EQ(m.spec.graphics[0].id, INT_MAX);
    EXPECT_EQ(m.spec.graphics[0].body, INT_MAX);
    ASSERT_TRUE(m.topology.has_value());
    EXPECT_EQ(m.topology->dof, 1);
}

TEST(Diagnostics, AllErrorsAreCollectedInLineOrder)
{
    // five independent mistakes, found by the parser (lines 2, 9) and by the checks
    // (lines 1, 3, 10): all five are listed, top to bottom
    CompiledModel m = compileText(R"pad(B 1 -5 1 1 1
B 2 10 1 1 4,5
C 1 LL 1 UL -1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 2
B1 1 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 2 P2 0 0 0 A2 0 0 1 R2 0 1 0
GRAVTY 0 0 -9.81
D 5 HYD VMAX 1
)pad",
                                  "m.pad");
    expectDiagnostics(m, {
        {"negative-mass", "m.pad:1:5: error: body 1 has a negative mass (-5 kg) [a mass is zero or positive, in kg]"},
        {"decimal-comma", "m.pad:2:12: error: body 2: '4,5' is not a number [use '.' as the decimal separator: 4.5]"},
        {"limits-reversed",
         "m.pad:3:8: error: joint 1: the lower limit LL = 1 rad is above the upper limit UL = -1 rad [swap LL and UL]"},
        {"unknown-keyword", "m.pad:9:1: error: unknown keyword 'GRAVTY' [did you mean 'GRAVITY'?]"},
        {"undefined-joint",
         "m.pad:10:1: error: drive on joint 5: joint 5 is not defined [use the id of a joint (C id …)]"},
    });
    EXPECT_EQ(m.diagnostics.errorCount(), 5u);
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
}

TEST(Diagnostics, ModelWithOneErrorHasNoTopology)
{
    // the same model loads and is analysed without the error, and is not with it
    const std::string good = std::string(kRevolute) + "D 1 HYD VMAX 1\n";
    CompiledModel ok = compileText(good, "m.pad");
    EXPECT_TRUE(ok.diagnostics.empty()) << listing(ok.diagnostics);
    EXPECT_TRUE(ok.ok());
    ASSERT_TRUE(ok.topology.has_value());
    EXPECT_EQ(ok.topology->dof, 1);
    EXPECT_EQ(ok.topology->totalMass, 1.0);

    CompiledModel bad = compileText(good + "D 1 HYD VMAX 2\n", "m.pad");
    EXPECT_EQ(bad.diagnostics.errorCount(), 1u);
    EXPECT_FALSE(bad.ok());
    EXPECT_FALSE(bad.topology.has_value());
}

TEST(Diagnostics, ForceKindsAreParsed)
{
    CompiledModel m = compileText(R"pad(B 1 10 1 1 1
C 1 T 2 LL 0 UL 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
F 1 POINT B 1 P 0.1 0.2 0.3 DIR 0 0 -1 MAG 250.5 LOCAL
F 2 TORQUE B 1 DIR 0 0 1 MAG SIN 10 0.5 1.5708 2
F 3 JOINT 1 MAG TABLE T 0 0 1 100 2 50
F 4 SPRING B1 0 P1 0 0 1 B2 1 P2 0 0 0 K 1000 L0 0.5 C 20
F 5 AERO B 1 P 0 0 0 AREA 2 CD 1.2 CL 0.3 RHO 1.1
F 6 POINT B 1 P 0 0 0 DIR 1 0 0 MAG TABLE Q 1 0 0 0.5 10 1 0
F 7 aero b 1 p 1 2 3 area 0.5 cd 0.8
F 8 TORQUE B 1 DIR 1 0 0 MAG SIN 1 2 3
)pad",
                                  "m.pad");
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    ASSERT_EQ(m.spec.forces.size(), 8u);
    const auto& f = m.spec.forces;
    using K = MagnitudeSpec::Kind;

    EXPECT_EQ(f[0].id, 1);
    EXPECT_EQ(f[0].kind, ForceKind::Point);
    EXPECT_EQ(f[0].body, 1);
    EXPECT_EQ(f[0].point, Eigen::Vector3d(0.1, 0.2, 0.3));
    EXPECT_EQ(f[0].dir, Eigen::Vector3d(0, 0, -1));
    EXPECT_EQ(f[0].mag.kind, K::Constant);
    EXPECT_EQ(f[0].mag.value, 250.5);
    EXPECT_TRUE(f[0].local);

    EXPECT_EQ(f[1].kind, ForceKind::Torque);
    EXPECT_EQ(f[1].dir, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(f[1].mag.kind, K::Sine);
    EXPECT_EQ(f[1].mag.amplitude, 10.0);
    EXPECT_EQ(f[1].mag.frequency, 0.5);
    EXPECT_EQ(f[1].mag.phase, 1.5708);
    EXPECT_TRUE(f[1].mag.hasOffset);
    EXPECT_EQ(f[1].mag.offset, 2.0);
    EXPECT_FALSE(f[1].local);

    EXPECT_EQ(f[2].kind, ForceKind::Joint);
    EXPECT_EQ(f[2].joint, 1);
    EXPECT_EQ(f[2].mag.kind, K::TableTime);
    EXPECT_EQ(f[2].mag.table, (std::vector<std::pair<double, double>>{{0, 0}, {1, 100}, {2, 50}}));

    EXPECT_EQ(f[3].kind, ForceKind::Spring);
    EXPECT_EQ(f[3].body, 0);
    EXPECT_EQ(f[3].point, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(f[3].body2, 1);
    EXPECT_EQ(f[3].point2, Eigen::Vector3d(0, 0, 0));
    EXPECT_EQ(f[3].stiffness, 1000.0);
    EXPECT_EQ(f[3].restLength, 0.5);
    EXPECT_TRUE(f[3].hasDamping);
    EXPECT_EQ(f[3].damping, 20.0);

    EXPECT_EQ(f[4].kind, ForceKind::Aero);
    EXPECT_EQ(f[4].area, 2.0);
    EXPECT_EQ(f[4].cd, 1.2);
    EXPECT_TRUE(f[4].hasCl);
    EXPECT_EQ(f[4].cl, 0.3);
    EXPECT_TRUE(f[4].hasRho);
    EXPECT_EQ(f[4].rho, 1.1);

    EXPECT_EQ(f[5].mag.kind, K::TableJoint);
    EXPECT_EQ(f[5].mag.joint, 1);
    EXPECT_EQ(f[5].mag.table, (std::vector<std::pair<double, double>>{{0, 0}, {0.5, 10}, {1, 0}}));

    // keywords are case-insensitive; AERO's optional values keep their defaults
    EXPECT_EQ(f[6].kind, ForceKind::Aero);
    EXPECT_EQ(f[6].point, Eigen::Vector3d(1, 2, 3));
    EXPECT_FALSE(f[6].hasCl);
    EXPECT_FALSE(f[6].hasRho);
    EXPECT_EQ(f[6].rho, 1.225);

    EXPECT_EQ(f[7].mag.kind, K::Sine);
    EXPECT_FALSE(f[7].mag.hasOffset);
    EXPECT_EQ(f[7].mag.offset, 0.0);
}

TEST(Diagnostics, GraphicShapesAreParsedAndMeshFoundNextToModel)
{
    const test::TempDir tmp("diagnostics_test");
    tmp.write("meshes/part.stl", "solid part\nendsolid part\n");
    const std::string text = std::string(kRevolute) + R"pad(G 1 B 1 BOX 1 2 3
G 2 B 1 CYL 0.1 1 POS 0 0 0.5 AXIS 1 0 0
G 3 B 1 TUBE 0.2 0.1 1 RHO 7850
G 4 B 1 SPHERE 0.5 COLOR 1 0 0
G 5 B 1 CONE 0.1 0.3 ROT 0 0 1 90
G 6 B 1 ELLIPSOID 1 2 3 MASS 3
G 7 B 0 PRISM 0.1 0 0 1 0 0 1
G 8 B 1 MESH "meshes/part.stl" SCALE 0.001
)pad";
    CompiledModel m = compileText(text, tmp.path("m.pad"));
    // the same model read from elsewhere does not find its mesh
    CompiledModel elsewhere = compileText(text, "m.pad");

    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    expectDiagnostics(elsewhere, {{"mesh-not-found",
                                   "m.pad:12:14: error: graphic 8: mesh file 'meshes/part.stl' not found (looked for "
                                   "./meshes/part.stl) [mesh paths are relative to the model file's folder]"}});
    ASSERT_EQ(m.spec.graphics.size(), 8u);
    const auto& g = m.spec.graphics;
    EXPECT_EQ(g[0].shape, ShapeKind::Box);
    EXPECT_EQ(g[0].dims, (std::vector<double>{1, 2, 3}));
    EXPECT_FALSE(g[0].hasPosition || g[0].hasAxis || g[0].hasRot || g[0].hasColor);
    EXPECT_FALSE(g[0].mass || g[0].rho);
    EXPECT_EQ(g[1].shape, ShapeKind::Cylinder);
    EXPECT_EQ(g[1].dims, (std::vector<double>{0.1, 1}));
    EXPECT_TRUE(g[1].hasPosition);
    EXPECT_EQ(g[1].position, Eigen::Vector3d(0, 0, 0.5));
    EXPECT_TRUE(g[1].hasAxis);
    EXPECT_EQ(g[1].axis, Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(g[2].shape, ShapeKind::Tube);
    EXPECT_EQ(g[2].dims, (std::vector<double>{0.2, 0.1, 1}));
    ASSERT_TRUE(g[2].rho);
    EXPECT_EQ(*g[2].rho, 7850.0);
    EXPECT_EQ(g[3].shape, ShapeKind::Sphere);
    EXPECT_EQ(g[3].dims, (std::vector<double>{0.5}));
    EXPECT_TRUE(g[3].hasColor);
    EXPECT_EQ(g[3].color, Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(g[4].shape, ShapeKind::Cone);
    EXPECT_TRUE(g[4].hasRot);
    EXPECT_EQ(g[4].rotAxis, Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(g[4].rotDeg, 90.0);
    EXPECT_EQ(g[5].shape, ShapeKind::Ellipsoid);
    ASSERT_TRUE(g[5].mass);
    EXPECT_EQ(*g[5].mass, 3.0);
    EXPECT_EQ(g[6].shape, ShapeKind::Prism);
    EXPECT_EQ(g[6].body, 0);
    EXPECT_EQ(g[6].dims, (std::vector<double>{0.1, 0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(g[7].shape, ShapeKind::Mesh);
    EXPECT_EQ(g[7].meshFile, "meshes/part.stl");
    EXPECT_TRUE(g[7].dims.empty());
    EXPECT_TRUE(g[7].hasScale);
    EXPECT_EQ(g[7].scale, 0.001);
}

TEST(Diagnostics, DriveKindsAreParsed)
{
    CompiledModel m = compileText(R"pad(B 1 10 1 1 1
B 2 10 1 1 1
B 3 10 1 1 1
B 4 10 1 1 1
B 5 10 1 1 1
C 1 T 2 LL 0 UL 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 2 T 2 LL 0 UL 1
B1 1 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 3
B1 2 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 3 P2 0 -1 0 A2 0 0 1 R2 0 1 0
C 4
B1 3 P1 0 1 0 A1 0 0 1 R1 0 1 0
B2 4 P2 0 -1 0 A2 0 0 1 R2 0 1 0
C 5 T 2
B1 4 P1 0 1 0 A1 0 0 1 R1 0 1 0
B2 5 P2 0 0 0 A2 0 0 1 R2 0 1 0
D 1 HYD VMAX 0.2 VMIN 0.3 FMAX 1000 FMIN 800
D 2 hyd PUMP 10 RPM 1500 BORE 0.1 ROD 0.05 PRESSURE 2e7
D 3 MOTOR W0 10 T0 100
D 4 SERVO KP 100 KI 0 KD 10 FMAX 50
D 5 PNEU F -200
)pad",
                                  "m.pad");
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    ASSERT_EQ(m.spec.drives.size(), 5u);
    const auto& d = m.spec.drives;
    using Params = std::vector<std::pair<std::string, double>>;
    EXPECT_EQ(d[0].joint, 1);
    EXPECT_EQ(d[0].kind, DriveKind::Hydraulic);
    EXPECT_EQ(d[0].params, (Params{{"VMAX", 0.2}, {"VMIN", 0.3}, {"FMAX", 1000}, {"FMIN", 800}}));
    EXPECT_EQ(d[0].hydraulic().vmax, 0.2);
    EXPECT_EQ(d[0].hydraulic().vmin, 0.3);
    EXPECT_EQ(d[0].hydraulic().fmax, 1000.0);
    EXPECT_EQ(d[0].hydraulic().fmin, 800.0);

    EXPECT_EQ(d[1].kind, DriveKind::Hydraulic);
    EXPECT_EQ(d[1].params,
              (Params{{"PUMP", 10}, {"RPM", 1500}, {"BORE", 0.1}, {"ROD", 0.05}, {"PRESSURE", 2e7}}));
    // flow 10 cm³ · 1500/min = 2.5e-4 m³/s; bore area π/4·0.1² m², annulus π/4·(0.1² − 0.05²) m²
    const double bore = std::numbers::pi / 4 * 0.01, annulus = std::numbers::pi / 4 * 0.0075;
    const auto h = d[1].hydraulic();
    EXPECT_NEAR(h.vmax, 2.5e-4 / bore, 1e-15);
    EXPECT_NEAR(h.vmin, 2.5e-4 / annulus, 1e-15);
    EXPECT_NEAR(h.fmax, 2e7 * bore, 1e-8);
    EXPECT_NEAR(h.fmin, 2e7 * annulus, 1e-8);
    EXPECT_NEAR(h.vmax, 0.0318309886, 1e-10);
    EXPECT_NEAR(h.fmax, 157079.6327, 1e-4);

    EXPECT_EQ(d[2].kind, DriveKind::Motor);
    EXPECT_EQ(d[2].params, (Params{{"W0", 10}, {"T0", 100}}));  // in the order written
    EXPECT_EQ(d[3].kind, DriveKind::Servo);
    EXPECT_EQ(d[3].params, (Params{{"KP", 100}, {"KI", 0}, {"KD", 10}, {"FMAX", 50}}));
    EXPECT_EQ(d[4].kind, DriveKind::Pneumatic);
    EXPECT_EQ(d[4].params, (Params{{"F", -200}}));
}

TEST(Diagnostics, WarningsDoNotStopTheModel)
{
    // a warning is reported, the model still loads and is analysed
    CompiledModel m = compileText(R"pad(B 1 5 1 1 3
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0.001
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
)pad",
                                  "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].code, "inertia-triangle");
    EXPECT_EQ(m.diagnostics.items()[0].severity, Severity::Warning);
    EXPECT_EQ(m.diagnostics.items()[1].code, "not-perpendicular");
    EXPECT_EQ(m.diagnostics.items()[1].severity, Severity::Warning);
    EXPECT_EQ(m.diagnostics.warningCount(), 2u);
    EXPECT_TRUE(m.ok());
    EXPECT_TRUE(m.topology.has_value());
}

}  // namespace

TEST(Diagnostics, ValuesInMessagesHaveTheirControlCharactersEscaped)
{
    // a value from a file or the command line (a quoted name, a path) may hold an escape
    // sequence or a NUL: a message shows it escaped, never sends it raw to a terminal
    const std::string raw = std::string("a\x1b[2Jb\tc\rd") + '\0' + "e\x7f";
    const Text t = trText("Diagnostics", "cannot write %1: %2").with(raw).with("line\nbreak");
    EXPECT_EQ(t.english(), "cannot write a\\x1b[2Jb\\tc\\rd\\x00e\\x7f: line\nbreak");
    EXPECT_EQ(escapeControls("plain ñandú"), "plain ñandú");  // UTF-8 untouched
}
