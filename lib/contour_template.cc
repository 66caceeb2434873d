#include "contour_template.h"

#include <cmath>

namespace ctrack {

namespace {

#include "silhouettes.inc"
#include "region_thresholds.inc"

// The regions as zones of the canonical box: row bands of the 64-row
// profile and which edges count (0 left, 1 right, 2 both). Front and back
// mean nothing in a frontal view, so the halves are left and right. Zones
// overlap: the upper limbs share rows with chest, back, abdomen and
// buttocks, and a point counts in every region whose zone holds it.
struct Zone {
    int row0, row1, side;
};
constexpr Zone kZones[kRegions] = {
    {0, 8, 2},    // head
    {8, 11, 2},   // neck
    {11, 16, 2},  // shoulders
    {16, 29, 0},  // chest
    {16, 29, 1},  // back
    {29, 36, 0},  // abdomen
    {29, 36, 1},  // buttocks
    {16, 36, 2},  // upper limbs
    {36, 64, 2},  // lower limbs
};

const char *const kNames[kRegions] = {"head", "neck", "shoulders", "chest", "back",
                                      "abdomen", "buttocks", "upper limbs", "lower limbs"};

} // namespace

const char *region_name(int r)
{
    return r >= 0 && r < kRegions ? kNames[r] : nullptr;
}

const RegionThresholds &default_thresholds()
{
    return kDefaultThresholds;
}

void profile_of(const uint8_t *mask, int stride, int x0, int y0, int x1, int y1, Profile *p)
{
    const int w = x1 - x0, h = y1 - y0;
    const double centre = (x0 + x1) / 2.0;
    for (int r = 0; r < kRows; r++) {
        p->edge[r][0] = p->edge[r][1] = Profile::kEmpty;
        if (w <= 0 || h <= 0)
            continue;
        const int y = y0 + (int)((r + 0.5) * h / kRows);
        const uint8_t *row = mask + (size_t)y * stride;
        int l = x0;
        while (l < x1 && !row[l])
            l++;
        if (l == x1)
            continue;
        int rr = x1 - 1;
        while (!row[rr])
            rr--;
        // Pixel centres, from the box's centre in box heights.
        p->edge[r][0] = (float)((l + 0.5 - centre) / h);
        p->edge[r][1] = (float)((rr + 0.5 - centre) / h);
    }
}

Vote classify(const Profile &p, const RegionThresholds &th)
{
    Vote best;
    float best_total = INFINITY;
    for (int s = 0; s < kSilhouettes; s++) {
        Vote v;
        float total = 0;
        for (int g = 0; g < kRegions; g++) {
            const Zone &z = kZones[g];
            float sum = 0;
            int n = 0, rows = 0;
            for (int r = z.row0; r < z.row1; r++) {
                rows++;
                if (p.empty(r))
                    continue;
                for (int side = 0; side < 2; side++)
                    if (z.side == 2 || z.side == side) {
                        sum += std::fabs(p.edge[r][side] - kSilhouette[s][r][side]);
                        n++;
                    }
            }
            const int present = z.side == 2 ? n / 2 : n;
            if (2 * present < rows) { // occluded or out of the frame: abstain
                v.distance[g] = -1;
                continue;
            }
            v.distance[g] = sum / n;
            v.voters++;
            v.yes += v.distance[g] <= th.t[g];
            total += v.distance[g];
        }
        v.score = v.voters >= kMinVoters ? (float)v.yes / v.voters : 0;
        v.silhouette = s;
        // The closest silhouette (mean distance over the voting regions)
        // speaks for the library, whatever the thresholds: the distances a
        // blob reports do not depend on them.
        const float mean = v.voters ? total / v.voters : INFINITY;
        if (mean < best_total) {
            best = v;
            best_total = mean;
        }
    }
    return best;
}

} // namespace ctrack
