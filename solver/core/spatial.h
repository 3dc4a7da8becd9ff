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

// The 6-vectors below are assembled from their 3-vector halves by head<3>()/tail<3>()
// (fixed-size blocks), not by Eigen's comma initializer, whose blocks are sized at run
// time: in the step loop that costs more than the arithmetic. The functions are a few
// dozen flops each and always inlined (PADROB_SPATIAL_INLINE): GCC at -O2 takes Eigen's
// expression templates for large code and would leave them as calls in the
// articulated-body passes.

#define PADROB_SPATIAL_INLINE [[gnu::always_inline]] inline

/// out = a b for 3×3 matrices (a may be an Isometry3d's linear() block, b a
/// transpose), column by column, the sums in Eigen's own order: GCC at -O2 leaves
/// Eigen's fixed 3×3 product as a call, which costs more than its 45 flops.
template <class A, class B>
PADROB_SPATIAL_INLINE void multiply3(const A& a, const B& b, Eigen::Matrix3d& out)
{
    for (int k = 0; k < 3; ++k) out.col(k) = a.col(0) * b(0, k) + a.col(1) * b(1, k) + a.col(2) * b(2, k);
}

/// a v for a 3×3 matrix (or block), likewise.
template <class A>
PADROB_SPATIAL_INLINE Eigen::Vector3d multiply3(const A& a, const Eigen::Vector3d& v)
{
    return a.col(0) * v(0) + a.col(1) * v(1) + a.col(2) * v(2);
}

/// a v for a 6×6 matrix, likewise: column by column on the stored doubles (Eigen's
/// assignment of the six-term sum stayed a call at -O2), each entry summed in the
/// same order, a(r,0) v(0) + a(r,1) v(1) + … + a(r,5) v(5).
PADROB_SPATIAL_INLINE Vector6d multiply6(const Matrix6d& a, const Vector6d& v)
{
    const double* m = a.data();  // column-major
    Vector6d out;
    double* o = out.data();
    for (int r = 0; r < 6; ++r) o[r] = m[r] * v(0);
    for (int k = 1; k < 6; ++k) {
        const double vk = v(k);
        for (int r = 0; r < 6; ++r) o[r] += m[6 * k + r] * vk;
    }
    return out;
}

/// Writes [v]× (the matrix with [v]× w = v × w) into the 3×3 block `s`, in place: a
/// 3×3 temporary just written and copied in would cost more than the skew itself.
template <class Block>
PADROB_SPATIAL_INLINE void setSkew(const Eigen::Vector3d& v, Block&& s)
{
    s(0, 0) = 0;
    s(0, 1) = -v.z();
    s(0, 2) = v.y();
    s(1, 0) = v.z();
    s(1, 1) = 0;
    s(1, 2) = -v.x();
    s(2, 0) = -v.y();
    s(2, 1) = v.x();
    s(2, 2) = 0;
}

/// Motion cross product v ×m m = [ω × m_ω; ω × m_v + v_O × m_ω] (RBDA eq. 2.31).
PADROB_SPATIAL_INLINE Vector6d crossMotion(const Vector6d& v, const Vector6d& m)
{
    // (3-vectors copied out: Eigen's cross on 6-vector segments is slower)
    const Eigen::Vector3d w = v.head<3>(), vo = v.tail<3>();
    const Eigen::Vector3d mw = m.head<3>(), mv = m.tail<3>();
    Vector6d out;
    out.head<3>() = w.cross(mw);
    out.tail<3>() = w.cross(mv) + vo.cross(mw);
    return out;
}

/// Force cross product v ×* f = [ω × n + v_O × f; ω × f] (RBDA eq. 2.32).
PADROB_SPATIAL_INLINE Vector6d crossForce(const Vector6d& v, const Vector6d& f)
{
    const Eigen::Vector3d w = v.head<3>(), vo = v.tail<3>();
    const Eigen::Vector3d n = f.head<3>(), fo = f.tail<3>();
    Vector6d out;
    out.head<3>() = w.cross(n) + vo.cross(fo);
    out.tail<3>() = w.cross(fo);
    return out;
}

/// A force vector moved from O to the point p: [n_O − p × f; f] (the moment about p).
PADROB_SPATIAL_INLINE Vector6d forceAboutPoint(const Vector6d& f, const Eigen::Vector3d& p)
{
    const Eigen::Vector3d n = f.head<3>(), fo = f.tail<3>();
    Vector6d out;
    out.head<3>() = n - p.cross(fo);
    out.tail<3>() = fo;
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
    PADROB_SPATIAL_INLINE Vector6d operator*(const Vector6d& v) const
    {
        const Eigen::Vector3d w = v.head<3>(), lin = v.tail<3>();
        Vector6d f;
        f.head<3>() = multiply3(Ibar, w) + h.cross(lin);
        f.tail<3>() = m * lin - h.cross(w);
        return f;
    }

    /// Writes the 6×6 matrix into `out`.
    PADROB_SPATIAL_INLINE void toMatrix(Matrix6d& out) const
    {
        out.topLeftCorner<3, 3>() = Ibar;
        setSkew(h, out.topRightCorner<3, 3>());
        setSkew(-h, out.bottomLeftCorner<3, 3>());  // [h]×ᵀ = [−h]×
        out.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
    }
};

/// The spatial inertia about O of a body of mass m [kg] with its centre of mass at the
/// world point c [m] and rotational inertia Ic about c in world axes [kg m^2], written
/// into `out`. Ic may be out.Ibar itself (the dynamics compute it there: copying a
/// 3×3 matrix just written costs more than the parallel-axis term).
PADROB_SPATIAL_INLINE void rigidInertiaAt(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& Ic,
                                          RigidInertia& out)
{
    out.m = m;
    out.h = m * c;
    if (&Ic != &out.Ibar) out.Ibar = Ic;
    // m([c]×)ᵀ[c]× = m(|c|² 1 − c cᵀ)
    out.Ibar.noalias() -= m * c * c.transpose();
    out.Ibar.diagonal().array() += m * c.squaredNorm();
}

}  // namespace solver
