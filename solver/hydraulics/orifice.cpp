#include "solver/hydraulics/orifice.h"

#include <cmath>

namespace solver::hydraulics {

double orificeRoot(double dp, double pLam)
{
    const double a = std::abs(dp);
    if (a >= pLam) return dp >= 0 ? std::sqrt(a) : -std::sqrt(a);
    return dp / std::sqrt(pLam);
}

double orificeSlope(double dp, double pLam)
{
    const double a = std::abs(dp);
    if (a >= pLam) return 0.5 / std::sqrt(a);
    return 1.0 / std::sqrt(pLam);
}

}  // namespace solver::hydraulics
