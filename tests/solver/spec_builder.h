#pragma once
// A small builder of ModelSpecs in C++ for tests that need no model text.
// Statements get consecutive line numbers, as a file would: a body one line, a
// joint its C line plus B1, B2 (and CL for T 1). Keyword values get the columns
// given to the setters (default: see each setter).

#include "solver/spec/model_spec.h"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace solver::test {

inline JointSide side(int body, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& a = Eigen::Vector3d::UnitZ(),
                      const Eigen::Vector3d& r = Eigen::Vector3d::UnitX())
{
    JointSide s;
    s.body = body;
    s.p = p;
    s.a = a;
    s.r = r;
    s.present = true;
    return s;
}

class SpecBuilder {
public:
    ModelSpec spec;

    /// `B id` (massless) at the next line.
    BodySpec& body(int id, const std::string& name = {})
    {
        BodySpec b;
        b.id = id;
        b.name = name;
        b.src.pos = {m_line++, 1};
        spec.bodies.push_back(b);
        return spec.bodies.back();
    }

    /// `B id m Ixx Iyy Izz [CG x y z]`.
    BodySpec& body(int id, double mass, const Eigen::Vector3d& inertia,
                   const Eigen::Vector3d& cg = Eigen::Vector3d::Zero(),
                   const std::string& name = {})
    {
        BodySpec& b = body(id, name);
        b.hasMass = true;
        b.mass = mass;
        b.inertia = inertia;
        b.hasCg = !cg.isZero();
        b.cg = cg;
        return b;
    }

    /// `C id [T type]` with its B1/B2 lines (and a CL line for T 1) at the next lines.
    JointSpec& joint(int id, JointType type, const JointSide& s1, const JointSide& s2,
                     const std::string& name = {})
    {
        JointSpec j;
        j.id = id;
        j.type = type;
        j.typeWritten = type != JointType::Revolute;
        j.name = name;
        j.src.pos = {m_line++, 1};
        j.side1 = s1;
        j.side1.src.pos = {m_line++, 1};
        j.side2 = s2;
        j.side2.src.pos = {m_line++, 1};
        spec.joints.push_back(j);
        return spec.joints.back();
    }

    /// A T 1 joint: as joint(), plus the CL line (CL1 value at column 5 of that line).
    JointSpec& actuator(int id, const JointSide& s1, const JointSide& s2,
                        const Eigen::Vector3d& cl1, const Eigen::Vector3d& cl2,
                        const std::string& name = {})
    {
        JointSpec& j = joint(id, JointType::Actuator, s1, s2, name);
        j.hasCl = true;
        j.cl1 = cl1;
        j.cl2 = cl2;
        j.src.at["CL1"] = {m_line, 5};
        j.src.at["CL2"] = {m_line, 20};
        ++m_line;
        return j;
    }

    /// Sets LL, UL, QI or VI of the joint with that id, its value at `column` of the C line.
    void set(int jointId, const std::string& key, double value, int column)
    {
        for (JointSpec& j : spec.joints) {
            if (j.id != jointId) continue;
            if (key == "LL") j.ll = value;
            if (key == "UL") j.ul = value;
            if (key == "QI") j.qi = value;
            if (key == "VI") j.vi = value;
            j.src.at[key] = {j.src.pos.line, column};
        }
    }

    /// `D joint HYD VMAX 1` at the next line.
    void drive(int jointId)
    {
        DriveSpec d;
        d.joint = jointId;
        d.params = {{"VMAX", 1.0}};
        d.src.pos = {m_line++, 1};
        spec.drives.push_back(d);
    }

    int nextLine() const { return m_line; }

private:
    int m_line = 1;
};

}  // namespace solver::test
