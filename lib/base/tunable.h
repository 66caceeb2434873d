// A tuning build (meson -Dtuning=true, never shipped) reads some of the
// engine's internal constants from the environment, for the sweeps of
// docs/tuning.md; a shipped build compiles them as constants:
//     CT_TUNABLE(kTime, "CTRACK_SIZE_TIME", 0.5);
#ifndef CTRACK_TUNABLE_H
#define CTRACK_TUNABLE_H

#ifdef CT_TUNING
#include <cstdlib>

namespace ctrack {

// The environment's value of `name` if set, else `value`.
inline double tunable(const char *name, double value)
{
    const char *s = std::getenv(name);
    return s ? std::atof(s) : value;
}

} // namespace ctrack

#define CT_TUNABLE(name, env, value) const double name = ::ctrack::tunable(env, value)
#else
#define CT_TUNABLE(name, env, value) constexpr double name = value
#endif

#endif
