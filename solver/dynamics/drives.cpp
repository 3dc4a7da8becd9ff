#include "solver/dynamics/drives.h"

#include "solver/hydraulics/actuator.h"

#include <algorithm>
#include <cmath>

namespace solver {

bool isPrescribed(const Model& model, const State& state, int i)
{
    if (state.limit[i] != LimitState::Free) return true;
    return model.drive[i].type == DriveType::Hydraulic && state.relief[i] == ReliefState::Closed;
}

double hydraulicCommandRate(const CompiledDrive& drive, double u)
{
    u = std::clamp(u, -1.0, 1.0);
    if (u > 0) return u * drive.vmax;
    if (u < 0) return u * drive.vmin;
    return 0.0;
}

double prescribedRate(const Model& model, const State& state, int i)
{
    if (state.limit[i] != LimitState::Free) return 0.0;
    const CompiledDrive& drive = model.drive[i];
    if (drive.type != DriveType::Hydraulic || state.relief[i] != ReliefState::Closed) {
        return state.qd[i];
    }
    const double rate = hydraulicCommandRate(drive, state.u[i]);
    const double dq = model.coordinateRate(i, state.q[i]);
    return dq != 0 ? rate / dq : 0.0;
}

double prescribedAcceleration(const Model& model, const State& state, int i)
{
    return prescribedAcceleration(model, state, i, model.coordinateMap(i, state.q[i]));
}

double prescribedAcceleration(const Model& model, const State& state, int i, const CoordinateMap& map)
{
    if (state.limit[i] != LimitState::Free) return 0.0;
    if (model.jointType[i] != JointType::Actuator) return 0.0;
    // L̇ = L'θ̇ held: θ̈ = −L''θ̇²/L'
    const double thd = state.qd[i];
    if (map.dq == 0 || thd == 0) return 0.0;
    return -map.ddq * thd * thd / map.dq;
}

double servoSetPoint(const CompiledDrive& drive, double u)
{
    u = std::clamp(u, -1.0, 1.0);
    return drive.setLow + 0.5 * (u + 1.0) * (drive.setHigh - drive.setLow);
}

double servoError(const Model& model, const State& state, int i)
{
    const CompiledDrive& drive = model.drive[i];
    if (drive.type != DriveType::Servo) return 0.0;
    return servoSetPoint(drive, state.u[i]) - model.coordinate(i, state.q[i]);
}

double driveForceLaw(const Model& model, const State& state, int i)
{
    if (model.drive[i].type == DriveType::None) return 0.0;
    return driveForceLaw(model, state, i, model.coordinateMap(i, state.q[i]));
}

double driveForceLaw(const Model& model, const State& state, int i, const CoordinateMap& map)
{
    const CompiledDrive& drive = model.drive[i];
    const double u = std::clamp(state.u[i], -1.0, 1.0);
    switch (drive.type) {
    case DriveType::None: return 0.0;
    case DriveType::Motor: {
        // linear torque–speed curve, in the modeler's coordinate
        if (!(drive.w0 > 0)) return u * drive.t0;
        const double speed = std::abs(map.dq * state.qd[i]);
        return speed < drive.w0 ? u * drive.t0 * (1.0 - speed / drive.w0) : 0.0;
    }
    case DriveType::Pneumatic: return u * drive.force;
    case DriveType::Servo: {
        const double e = servoSetPoint(drive, state.u[i]) - map.q;
        const double edot = -map.dq * state.qd[i];
        const double force = drive.kp * e + drive.ki * state.servoIntegral[i] + drive.kd * edot;
        return std::clamp(force, -drive.servoFmax, drive.servoFmax);
    }
    case DriveType::FluidPower: {
        const Eigen::Index k = kFluidStates * static_cast<Eigen::Index>(drive.circuit);
        return hydraulics::actuatorForce(model.circuits[static_cast<std::size_t>(drive.circuit)], state.fluid[k + 1],
                                         state.fluid[k + 2], map.dq * state.qd[i]);
    }
    case DriveType::Hydraulic:
        switch (state.relief[i]) {
        case ReliefState::Closed: return 0.0;
        case ReliefState::OpenExtending: return drive.fmax;
        case ReliefState::OpenRetracting: return -drive.fmin;
        }
        return 0.0;
    }
    return 0.0;
}

}  // namespace solver
