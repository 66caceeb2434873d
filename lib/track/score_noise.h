// How far a detector's boxes stray by their scores, learnt as the tracker
// runs. A detector places the boxes it is less sure of less precisely:
// over the six MOTChallenge sequences' public detections, the centres of
// the boxes scoring 0.5 to 0.8 lie about twice as far from the person as
// those scoring 0.98 or more. A filter that trusted every box alike would
// be pulled off by the worse ones, and one that trusted them by a fixed
// curve of the score would fit one detector's scale. So each detection's
// noise is detection_noise times the factor its score's boxes earned:
// the root of the mean squared centre innovation of the confirmed tracks'
// detections whose scores fall in its twentieth of [0, 1] over that of all
// of them (docs/tuning.md, "A detection's noise by its score").
#ifndef CTRACK_SCORE_NOISE_H
#define CTRACK_SCORE_NOISE_H

namespace ctrack {

class ScoreNoise {
public:
    // Forgets what it learnt.
    void reset();
    // A confirmed track's detection: its score, and its centre's squared
    // innovation about the prediction in the track's heights squared (the
    // mean of both axes; Track::centre_innovation2()). Non-finite ones are
    // ignored.
    void observe(float score, double innovation2);
    // The factor on detection_noise for a detection of this score: 1 until
    // kMinSamples innovations are known; a score's own mean leans toward
    // the mean of all by kPrior innovations' worth, so that a rare score
    // stays near 1; within [kMinFactor, kMaxFactor].
    double factor(float score) const;

    static constexpr double kMinSamples = 50;
    static constexpr double kMinFactor = 0.5, kMaxFactor = 3;

private:
    static constexpr int kBins = 20; // scores in [0, 1] by twentieths (score_bin())
    double sum_[kBins] = {};
    double count_[kBins] = {};
    double sum_all_ = 0, count_all_ = 0;
};

} // namespace ctrack

#endif
