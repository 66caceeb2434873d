// The scale of a detector's scores, learnt as the tracker runs: how the
// scores of its boxes are spread, and the score its best 40% reach.
//
// The engine keeps two. One learns the boxes that may start a track
// (start_score and above): a track is confirmed once one of its
// detections reached confirm_score (ct_config), and a detector whose
// scores rarely or never reach it (a confidence capped at 0.9, a score on
// a scale of its own) would then confirm almost nothing. So the score
// asked for is never above the one its best 40% of boxes reach. Over a
// whole sequence of the public MOTChallenge detections that is 0.96 to
// 0.99, above confirm_score's default; it is lower only in the first
// frames, while few scores are known. With a detector that is never that
// sure, its own best boxes confirm tracks (docs/tuning.md,
// "Confirmation").
//
// The other learns every box from low_score up: the scale on which
// high_score and start_score are read (Engine::sort_detections(),
// docs/tuning.md, "The detector's scale for starting tracks").
#ifndef CTRACK_SCORE_SCALE_H
#define CTRACK_SCORE_SCALE_H

#include <algorithm>
#include <cstdint>

namespace ctrack {

// Score's bin of `bins` equal ones over [0, 1]; scores outside it (or NaN)
// count at its ends.
inline int score_bin(float score, int bins)
{
    return score >= 1.0f ? bins - 1 : score > 0.0f ? (int)(score * bins) : 0;
}

class ScoreScale {
public:
    // Forgets what it learnt.
    void reset();
    // A detection's score.
    void observe(float score);
    // How many scores it has learnt (halved with the counts past 2^20).
    uint32_t count() const { return total_; }
    // The score the best 40% of the boxes learnt reach (the lower edge of
    // its hundredth of [0, 1]); 1 before any.
    float best() const;
    // The score a tentative track's detection must reach to confirm it:
    // `wanted` (confirm_score), or lower when the detector's best 40% of
    // boxes score less (after observe()s; `wanted` before any).
    float confirm(float wanted) const { return total_ == 0 ? wanted : std::min(wanted, best()); }

private:
    static constexpr int kBins = 100; // scores in [0, 1] by hundredths
    uint32_t count_[kBins] = {};
    uint32_t total_ = 0;
};

} // namespace ctrack

#endif
