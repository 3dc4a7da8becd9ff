#pragma once
// The compiled fluid-power circuit (docs/hydraulics.md): the oil, the pumps, and one
// circuit per CYL/HMOTOR drive (its valve section and its actuator's chambers). The
// laws that use them are in solver/hydraulics/; they live here because the Model
// (core/model.h) holds them. Pressures are gauge [Pa] (tank = 0), flows [m^3/s].

#include "solver/core/kinds.h"

#include <algorithm>
#include <string>

namespace solver {

inline constexpr double kDefaultBulkModulus = 1.2e9;    ///< FLUID BULK [Pa]
inline constexpr double kDefaultLaminarPressure = 2e5;  ///< FLUID LAMINAR [Pa]
inline constexpr double kDefaultSpoolTau = 0.05;        ///< TAU [s]
inline constexpr double kDefaultMotorLineVolume = 1e-3; ///< HMOTOR VOLUME, each line [m^3]
/// CYL DEAD, each side: this much [m^3] (hoses and fittings) plus kDefaultDeadFraction
/// of the side's swept volume.
inline constexpr double kDefaultDeadVolume = 2.5e-4;
inline constexpr double kDefaultDeadFraction = 0.05;
/// The port relief valves open at the pump's p_max and pass the section's nominal flow
/// Qn at this fraction above it (a linear characteristic).
inline constexpr double kReliefOverride = 0.1;

/// A spool opening |x| below this is closed for the pump (a load-sensing pump ignores
/// the section, and its flow is not demanded): the spool's exponential approach to 0
/// would otherwise never close it.
inline constexpr double kSpoolClosed = 1e-3;

struct CompiledFluid {
    double bulk = kDefaultBulkModulus;        ///< β [Pa]
    double laminar = kDefaultLaminarPressure; ///< p_lam [Pa]
};

struct CompiledPump {
    int id = 0;
    std::string name;
    double qmax = 0;    ///< [m^3/s]
    double pmax = 0;    ///< [Pa]
    bool loadSensing = false;
    double margin = 0;  ///< Δp_ls [Pa] (load-sensing only)
    /// It feeds sections and every one is post-compensated (POST, flow sharing): when
    /// saturated it shares Qmax out instead of its supply falling (set with the circuits).
    bool allPost = false;
};

enum class ActuatorKind { Cylinder, Motor };

/// One CYL/HMOTOR drive: a 4/3 closed-centre proportional valve section fed by a pump,
/// and the actuator's two chambers A (pushes q up) and B.
struct CompiledCircuit {
    int joint = -1;   ///< tree index of the driven joint
    int pump = -1;    ///< index in Model::pumps
    ActuatorKind kind = ActuatorKind::Cylinder;
    // valve section
    double qn = 0;    ///< nominal flow [m^3/s] at the pressure drop dpn
    double dpn = 0;   ///< [Pa]
    double k = 0;     ///< flow coefficient Qn/√Δpn [m^3/(s √Pa)]
    double tau = kDefaultSpoolTau;  ///< spool time constant [s]
    Compensation comp = Compensation::None;
    double reliefGain = 0;  ///< port relief: flow per Pa above p_max [m^3/(s Pa)]
    // actuator: a cylinder's areas [m^2] or a motor's displacement [m^3/rad] (areaA = areaB)
    double areaA = 0, areaB = 0;
    double deadA = 0, deadB = 0;  ///< CYL: dead volumes; HMOTOR: the line volumes [m^3]
    double lower = 0, upper = 0;  ///< CYL: the stroke (LL, UL) in the modeler's coordinate [m]
    double friction = 0;          ///< viscous [N s/m or N m s/rad]
    bool hasP0 = false;
    double p0A = 0, p0B = 0;      ///< P0 [Pa]; without it the Simulation finds the holding pressures

    /// Chamber volumes at the modeler's coordinate q [m^3] (a cylinder's never below its dead volume).
    /// (Inline, as the other laws the circuits evaluate at every stage: hydraulics/*.h.)
    double volumeA(double q) const
    {
        if (kind == ActuatorKind::Motor) return deadA;
        return deadA + areaA * std::max(0.0, q - lower);
    }
    double volumeB(double q) const
    {
        if (kind == ActuatorKind::Motor) return deadB;
        return deadB + areaB * std::max(0.0, upper - q);
    }
};

}  // namespace solver
