// How tall a detector's people are where they stand, learnt as the tracker
// runs, and the detections that disagree with it. On a camera over a
// ground, a person's height in pixels is close to a line in the row of
// their feet (person_size.h); the line here is fitted by least squares to
// the boxes of the confirmed tracks' detections, each weighing less with
// its age (a time constant of seconds), so that a moving camera's changing
// view is followed. A detection far taller or shorter than the line says
// for its feet is rarely a person (a detector's false positive on a window
// or a bag, a box around part of a person or around a group): the tracker
// ignores it (docs/tuning.md, "Size gate").
#ifndef CTRACK_SIZE_GATE_H
#define CTRACK_SIZE_GATE_H

#include "ctrack/ctrack.h"

namespace ctrack {

class SizeGate {
public:
    // The gate, a natural log ratio (ct_config::size_gate; 0: none).
    void set_gate(float gate);
    // Forgets what it learnt.
    void reset() { w_ = sy_ = sh_ = syy_ = syh_ = 0; }
    // The sums age by dt seconds (at the start of a step).
    void age(double dt);
    // A box (top, height; frame pixels) that a confirmed track's detection
    // gave this step.
    void observe(double top, double height);
    // Whether the line is known (enough weight behind it).
    bool known() const;
    // The expected height of a person whose feet are at row y (known()).
    double height_at(double y) const;
    // Whether detection d's height is within the gate of the expected
    // height; always while the line is unknown, or with no gate.
    bool admits(const ct_detection &d) const;

private:
    // The heights admitted, as ratios to the expected one: exp(-gate),
    // exp(gate); 0 with no gate.
    double lo_ = 0, hi_ = 0;
    // Weighted sums of 1, y, h, y^2 and y h over the observed boxes (y the
    // feet row, h the height).
    double w_ = 0, sy_ = 0, sh_ = 0, syy_ = 0, syh_ = 0;
};

} // namespace ctrack

#endif
