// The tracks' appearance templates, kept in slots, and this step's
// descriptors of the detections: what DDIS compares in association and
// re-identification.
#ifndef CTRACK_TEMPLATES_H
#define CTRACK_TEMPLATES_H

#include <cstdint>
#include <vector>

#include "base/counters.h"
#include "base/memory.h"

#include "appearance/appearance.h"
#include "base/planes.h"
#include "track/track.h"

namespace ctrack {

class TemplateBank {
public:
    // This step's frame and detections, and the counters its DDIS and
    // template builds add to. A detection is described when it is first
    // compared or makes a template, at most once a step: only those a gate
    // lets near a track cost anything. img, dets and counters must stay
    // valid until the step ends.
    void begin(const Planes &img, const ct_detection *dets, size_t n, Counters *counters);
    // DDIS of this step's detection det against the track's template; a
    // track without one looks like anything (1).
    double similarity(const Track &t, int det);
    // Templates: made when a track is confirmed, remade from its detection
    // at most every half second while nothing occludes it. A template is
    // built in a slot that no track points to, in `tracks`, in `saved` (the
    // tracks as they were before the step, which a failed step restores) or
    // in `kept` (those a failed priming restores; may be null), and only
    // then does the track take it: a failure leaves every restored track's
    // template untouched.
    void learn(Vec<Track> &tracks, const Vec<Track> &saved, const Vec<Track> *kept,
               int64_t t_us);
    size_t memory_bytes() const;

private:
    // Detection det's descriptors, described on first use.
    const float *descriptors(int det);

    Vec<Template> templates_;
    Vec<char> slot_used_;
    Planes img_;
    const ct_detection *dets_ = nullptr;
    Counters *counters_ = nullptr;
    Vec<int> desc_of_;    // per detection: its descriptors' slot, or -1
    Vec<float> det_desc_; // described detections, kPoints * kDescDim each
    Describer describer_;
    Ddis ddis_;
};

} // namespace ctrack

#endif
