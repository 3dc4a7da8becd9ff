#pragma once
// Spatial (6D) algebra in Plücker coordinates, the small part the solver needs
// (Featherstone, "Rigid Body Dynamics Algorithms" (RBDA), ch. 2).
//
// Every spatial vector here is in world axes and taken about the world origin O:
// - a motion vector is [ω; v_O] (dim 6): the angular velocity [rad/s] and the
//   velocity [m/s] of the body-fixed point that is passing through O;
// - a force vector is [n_O; f] (dim 6): the moment about O [N m] and the force [N].
// Referring everything to one point removes the body-to-body transforms of the
// algorithms (the articulated inertias of children add directly to their parent's).

#include <Eigen/Core>

namespace solver {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// [v]×: the matrix with [v]× w = v × w.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    // clang-format off
    s <<      0, -v.z(),  v.y(),
          v.z(),      0, -v.x(),
         -v.y(),  v.x(),      0;
    // clang-format on
    return s;
}

/// Motion cross product v ×m m = [ω × m_ω; ω × m_v + v_O × m_ω] (RBDA eq. 2.31).
inline Vector6d crossMotion(const Vector6d& v, const Vector6d& m)
{
    // (3-vectors copied out: Eigen's cross on 6-vector segments is slower)
    const Eigen::Vector3d w = v.head<3>(), vo = v.tail<3>();
    const Eigen::Vector3d mw = m.head<3>(), mv = m.tail<3>();
    Vector6d out;
    out << w.cross(mw), w.cross(mv) + vo.cross(mw);
    return out;
}

/// Force cross product v ×* f = [ω × n + v_O × f; ω × f] (RBDA eq. 2.32).
inline Vector6d crossForce(const Vector6d& v, const Vector6d& f)
{
    const Eigen::Vector3d w = v.head<3>(), vo = v.tail<3>();
    const Eigen::Vector3d n = f.head<3>(), fo = f.tail<3>();
    Vector6d out;
    out << w.cross(n) + vo.cross(fo), w.cross(fo);
    return out;
}

/// A force vector moved from O to the point p: [n_O − p × f; f] (the moment about p).
inline Vector6d forceAboutPoint(const Vector6d& f, const Eigen::Vector3d& p)
{
    const Eigen::Vector3d n = f.head<3>(), fo = f.tail<3>();
    Vector6d out;
    out << n - p.cross(fo), fo;
    return out;
}

/// A rigid body's spatial inertia about O in world axes, stored by its parts (RBDA
/// eq. 2.63): mass m [kg], first moment h = m c [kg m] (c: world centre of mass) and
/// rotational inertia about O, Ī = I_c + m([c]×)ᵀ[c]× [kg m^2]. As a 6×6 matrix it is
/// [[Ī, [h]×], [[h]×ᵀ, m 1]]; the product with a motion vector costs 30 flops, not 36
/// multiply-adds, and the kinetic energy is ½ vᵀ I v.
struct RigidInertia {
    double m = 0;
    Eigen::Vector3d h = Eigen::Vector3d::Zero();
    Eigen::Matrix3d Ibar = Eigen::Matrix3d::Zero();

    /// I·v = [Ī ω + h × v_O; m v_O − h × ω] (a force vector).
    Vector6d operator*(const Vector6d& v) const
    {
        const Eigen::Vector3d w = v.head<3>(), lin = v.tail<3>();
        Vector6d f;
        f << Ibar * w + h.cross(lin), m * lin - h.cross(w);
        return f;
    }

    /// Writes the 6×6 matrix into `out`.
    void toMatrix(Matrix6d& out) const
    {
        const Eigen::Matrix3d hx = skew(h);
        out.topLeftCorner<3, 3>() = Ibar;
        out.topRightCorner<3, 3>() = hx;
        out.bottomLeftCorner<3, 3>() = hx.transpose();
        out.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
    }
};

/// The spatial inertia about O of a body of mass m [kg] with its centre of mass at the
/// world point c [m] and rotational inertia Ic about c in world axes [kg m^2].
inline RigidInertia rigidInertiaAt(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic)
{
    RigidInertia I;
    I.m = m;
    I.h = m * c;
    I.Ibar = Ic;
    // m([c]×)ᵀ[c]× = m(|c|² 1 − c cᵀ)
    I.Ibar.noalias() -= m * c * c.transpose();
    I.Ibar.diagonal().array() += m * c.squaredNorm();
    return I;
}

}  // namespace solver
