#include "solver/core/model.h"

#include <algorithm>

namespace solver {

int Model::jointIndex(int id) const
{
    // linear: for look-ups outside the step loop
    for (int i = 0; i < nb; ++i) {
        if (jointId[i] == id) return i;
    }
    return -1;
}

int Model::bodyIndex(int id) const
{
    if (id < 0) return -1;  // (the massless bodies of free joints)
    for (int i = 0; i < nb; ++i) {
        if (bodyId[i] == id) return i;
    }
    return -1;
}

double Model::coordinate(int i, double theta) const
{
    return jointType[i] == JointType::Actuator ? lengthLaw[i].length(theta) : theta;
}

double Model::coordinateRate(int i, double theta) const
{
    return jointType[i] == JointType::Actuator ? lengthLaw[i].lengthRate(theta) : 1.0;
}

CoordinateMap Model::coordinateMap(int i, double theta) const
{
    CoordinateMap map;
    if (jointType[i] == JointType::Actuator) {
        lengthLaw[i].lengthDerivatives(theta, map.q, map.dq, map.ddq);
    } else {
        map.q = theta;
    }
    return map;
}

}  // namespace solver
