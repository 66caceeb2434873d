#include "pixels/camera_motion.h"

#include <cstdlib>

namespace ctrack {

namespace {

// A shift is the camera's when its profiles' mean difference is under this
// share of the unshifted one's: people walking change a few columns'
// sums, a camera that moves all of them.
constexpr double kBetter = 0.6;

// The mean absolute difference of now[i] and before[i - shift] where both
// exist.
double mean_difference(const int32_t *now, const int32_t *before, int n, int shift)
{
    long long sum = 0;
    int count = 0;
    for (int i = 0; i < n; i++) {
        const int j = i - shift;
        if (j < 0 || j >= n)
            continue;
        sum += std::llabs((long long)now[i] - before[j]);
        count++;
    }
    return count ? (double)sum / count : 0.0;
}

} // namespace

bool profile_shifted(const int32_t *now, const int32_t *before, int n, int reach)
{
    if (n < 4 * reach)
        return false;
    const double still = mean_difference(now, before, n, 0);
    for (int s = -reach; s <= reach; s++)
        if (s != 0 && mean_difference(now, before, n, s) < kBetter * still)
            return true;
    return false;
}

} // namespace ctrack
