#pragma once
// The length law of a pivoted linear actuator (T 1 joint): its length as a function
// of the joint angle, and the angle wrapping it needs. Part of the compiled Model
// (core/model.h), so it lives here, below every other solver folder.

#include <optional>

namespace solver {

/// Wraps an angle to (−π, π] [rad].
double wrapAngle(double angle);

/// Length law of a T 1 actuator: L²(θ) = c0 + c1 cos θ + c2 sin θ, with L the
/// distance between CL1 (on side 1's body) and CL2 (on side 2's body) [m] and θ
/// the joint angle [rad]. Writing c1 = ρ cos φ, c2 = ρ sin φ, the longest length
/// is reached at θ = φ and the shortest at θ = φ + π (the dead points, dL/dθ = 0).
struct ActuatorLengthLaw {
    double c0 = 0;  ///< [m^2]
    double c1 = 0;  ///< [m^2]
    double c2 = 0;  ///< [m^2]

    double rho() const;  ///< ρ = hypot(c1, c2) [m^2]
    double phi() const;  ///< φ = atan2(c2, c1): angle of the longest length [rad]
    double minLength() const;  ///< sqrt(c0 − ρ) [m]
    double maxLength() const;  ///< sqrt(c0 + ρ) [m]
    double angleOfMaxLength() const;  ///< φ wrapped to (−π, π] [rad]
    double angleOfMinLength() const;  ///< φ + π wrapped to (−π, π] [rad]

    double lengthSquared(double angle) const;  ///< L²(θ) [m^2]
    double length(double angle) const;  ///< L(θ) [m]
    /// dL/dθ = (c2 cos θ − c1 sin θ) / (2 L) [m/rad]; 0 where L = 0.
    double lengthRate(double angle) const;
    /// d²L/dθ² = (c0 − L² − 2 (dL/dθ)²) / (2 L) [m/rad^2] (from differentiating
    /// L² = c0 + c1 cos θ + c2 sin θ twice); 0 where L = 0.
    double lengthSecondDerivative(double angle) const;
    /// L [m], dL/dθ [m/rad] and d²L/dθ² [m/rad^2] at once (one sine and cosine, one
    /// square root), for the step loop; the same values as the three functions above.
    void lengthDerivatives(double angle, double& length, double& rate, double& secondRate) const;
    /// The same from cos θ and sin θ already found (the kinematics turn the joint by θ).
    void lengthDerivativesAt(double cosAngle, double sinAngle, double& length, double& rate,
                             double& secondRate) const;
    /// dθ/dL = 1 / (dL/dθ) [rad/m]; infinite at a dead point.
    double angleRate(double angle) const;
    /// Angle whose length is `length` [m], on the branch whose angle (wrapped to
    /// (−π, π]) is nearest to 0; nullopt when the length is outside
    /// [minLength, maxLength] by more than `tolerance` [m] or ρ = 0. Lengths
    /// within the tolerance are clamped to the range.
    std::optional<double> angle(double length, double tolerance = 1e-9) const;
    /// Same with the branch nearest to `near` [rad] (for following a motion).
    std::optional<double> angleNear(double length, double near, double tolerance = 1e-9) const;
};

}  // namespace solver
