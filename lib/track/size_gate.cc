#include "track/size_gate.h"

#include <cmath>

#include "base/tunable.h"

namespace ctrack {

namespace {

// How fast an observation's weight fades, in seconds.
CT_TUNABLE(kTime, "CTRACK_SIZE_TIME", 0.5);
// The line speaks once this much weight stands behind it.
CT_TUNABLE(kMinWeight, "CTRACK_SIZE_WEIGHT", 10.0);

} // namespace

void SizeGate::age(double dt)
{
    if (!(dt > 0))
        return;
    const double f = std::exp(-dt / kTime);
    w_ *= f;
    sy_ *= f;
    sh_ *= f;
    syy_ *= f;
    syh_ *= f;
}

void SizeGate::observe(double top, double height)
{
    if (!std::isfinite(top) || !(height > 0) || !std::isfinite(height))
        return;
    const double y = top + height;
    w_ += 1;
    sy_ += y;
    sh_ += height;
    syy_ += y * y;
    syh_ += y * height;
}

bool SizeGate::known() const
{
    return w_ >= kMinWeight;
}

double SizeGate::height_at(double y) const
{
    const double my = sy_ / w_, mh = sh_ / w_, vy = syy_ / w_ - my * my;
    // Feet all on one row (or nearly): the mean height.
    const double slope = vy > 1.0 ? (syh_ / w_ - my * mh) / vy : 0.0;
    return mh + slope * (y - my);
}

void SizeGate::set_gate(float gate)
{
    lo_ = gate > 0 ? std::exp(-(double)gate) : 0;
    hi_ = gate > 0 ? std::exp((double)gate) : 0;
}

bool SizeGate::admits(const ct_detection &d) const
{
    if (!(hi_ > 0) || !known())
        return true;
    const double h = height_at((double)d.top + d.height);
    // A line that reaches no height there (past the horizon) says nothing.
    if (!(h > 1))
        return true;
    return d.height >= lo_ * h && d.height <= hi_ * h;
}

} // namespace ctrack
