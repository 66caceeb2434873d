// Constant-velocity Kalman filter of one coordinate, driven by elapsed time.
#ifndef CTRACK_MOTION_H
#define CTRACK_MOTION_H

namespace ctrack {

// State [position, velocity] with a 2x2 covariance. Process noise is white
// acceleration of standard deviation `accel` (units per second squared), so
// a step twice as long grows the uncertainty as it should: dropped frames
// and variable frame rates need no special case.
struct Axis {
    double x = 0, v = 0;
    double p00 = 0, p01 = 0, p11 = 0;

    void init(double z, double pos_sd, double vel_sd)
    {
        x = z;
        v = 0;
        p00 = pos_sd * pos_sd;
        p01 = 0;
        p11 = vel_sd * vel_sd;
    }

    void predict(double dt, double accel)
    {
        if (dt <= 0)
            return;
        x += v * dt;
        double q = accel * accel, dt2 = dt * dt;
        double n00 = p00 + 2 * dt * p01 + dt2 * p11 + q * dt2 * dt2 / 4;
        double n01 = p01 + dt * p11 + q * dt2 * dt / 2;
        double n11 = p11 + q * dt2;
        p00 = n00;
        p01 = n01;
        p11 = n11;
    }

    // The variance of a measurement about the prediction: the position's
    // and the measurement's own.
    double innovation_var(double meas_sd) const { return p00 + meas_sd * meas_sd; }

    // The normalized innovation squared of a measurement z: about 1 on
    // average while the filter's noises describe the motion it sees.
    double nis(double z, double meas_sd) const
    {
        const double e = z - x;
        return e * e / innovation_var(meas_sd);
    }

    void update(double z, double meas_sd)
    {
        double s = innovation_var(meas_sd);
        double k0 = p00 / s, k1 = p01 / s;
        double innov = z - x;
        x += k0 * innov;
        v += k1 * innov;
        double n00 = (1 - k0) * p00;
        double n01 = (1 - k0) * p01;
        double n11 = p11 - k1 * p01;
        p00 = n00;
        p01 = n01;
        p11 = n11;
    }
};

} // namespace ctrack

#endif
