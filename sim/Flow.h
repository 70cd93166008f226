#pragma once
// A velocity field that carries the contours: the fluid solver or an analytic expression.
#include "sim/Geometry.h"

namespace vf::sim {

class Flow {
public:
    virtual ~Flow() = default;

    // Advances the flow from time() to time() + dt. Afterwards velocity(p, t) is defined for every
    // t in [time() - dt, time()], so contour advection (eq. 1) can sample inside the step.
    virtual void advance(double dt) = 0;
    virtual double time() const = 0;
    // Sets the clock to t with no step in progress, as a restored snapshot continues.
    virtual void setTime(double t) = 0;

    // Velocity in canvas units per second at canvas point p and time t.
    virtual Vec2 velocity(Vec2 p, double t) const = 0;
    // Vorticity (curl of the velocity, 1/s) at p and time t, for the turbulence term (eq. 5).
    virtual double vorticity(Vec2 p, double t) const = 0;
};

} // namespace vf::sim
