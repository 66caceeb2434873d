// Counting: the lines that confirmed tracks cross and the zones they enter,
// leave and stay in (ct_tracker_add_line(), ct_tracker_add_zone()), as
// events each step and running counts.
#ifndef CTRACK_COUNTER_H
#define CTRACK_COUNTER_H

#include <cstddef>
#include <cstdint>

#include "base/memory.h"
#include "count/geometry.h"
#include "ctrack/ctrack.h"
#include "track/track.h"

namespace ctrack {

class Counter {
public:
    // Check a line or a zone (already read from the caller's struct) and
    // add it: CT_OK, or the error with its message in msg. A failure, a
    // refusal or a throw (memory), changes nothing. Tracks started at or
    // before last_us (the last step's time; INT64_MIN before any) take
    // their side of it from their next box, not their first.
    int add_line(const ct_line &line, int64_t last_us, int32_t *index, char *msg, size_t len);
    int add_zone(const ct_zone &zone, int64_t last_us, int32_t *index, char *msg, size_t len);

    // One step at t_us: the engine's tracks (the non-tentative ones count)
    // and the boxes reported for them. Throws (memory) only before it
    // changes anything.
    void step(int64_t t_us, const Vec<Track> &tracks, const Vec<ct_track> &reported);
    // Forgets the tracks (their sides, the occupants) and the last step's
    // events; the lines, the zones and their counts stay.
    void forget_tracks() noexcept;

    const Vec<ct_event> &events() const { return events_; }
    const Vec<ct_line_count> &line_counts() const { return line_counts_; }
    const Vec<ct_zone_count> &zone_counts() const { return zone_counts_; }
    const Vec<ct_occupant> &occupants() const { return occupants_; }
    size_t memory_bytes() const;

private:
    struct Line {
        Pt a, b;
        double hysteresis;
        int64_t added_us; // add_line()'s last_us
    };
    struct Zone {
        int first, n; // its corners in corners_
        double hysteresis;
        int64_t added_us;
    };
    // A confirmed track as counting follows it.
    struct Follow {
        uint64_t id;
        Pt last; // its anchor when last seen
    };
    // A follow's side of a line: -1 left, +1 right, 0 not known yet; and
    // where it was last seen on that side.
    struct LineState {
        int side;
        Pt on_side;
    };
    // Whether a follow is in a zone: 1, 0, or -1 not known yet; and since
    // when (its entry, or its first sighting when it started there).
    struct ZoneState {
        int inside;
        int64_t since_us;
    };
    // A non-tentative track this step.
    struct Live {
        uint64_t id;
        bool seen;      // seen this step, with its anchor and box height:
        Pt anchor;
        double height;
        Pt start;       // its first observed anchor, and when
        int64_t start_us;
    };
    // What a step works on: the state it makes, swapped in at its end.
    struct Next {
        Vec<Follow> follows;
        Vec<LineState> lines;  // follows x lines_
        Vec<ZoneState> zones;  // follows x zones_
        Vec<ct_event> events;
        Vec<ct_occupant> occupants;
        Vec<ct_line_count> line_counts;
        Vec<ct_zone_count> zone_counts;
    };

    // Whether name is free, and the name a line or zone gets (its own, or
    // prefix<index>); or the error.
    int take_name(const char *name, const char *prefix, size_t index, char *out, char *msg,
                  size_t len) const;
    void gather(const Vec<Track> &tracks, const Vec<ct_track> &reported);
    void reserve(Next &n) const;
    // A follow's states, from its first sighting.
    void start(Next &n, const Live &l) const;
    void observe(Next &n, size_t f, const Live &l, int64_t t_us) const;
    void end(Next &n, size_t old, int64_t t_us) const;
    void list_occupants(Next &n, int64_t t_us) const;
    static void emit(Next &n, int kind, int index, uint64_t id, int64_t t_us, Pt at);

    Vec<Line> lines_;
    Vec<Zone> zones_;
    Vec<Pt> corners_;
    Vec<Follow> follows_; // in increasing id
    Vec<LineState> line_states_;
    Vec<ZoneState> zone_states_;
    Vec<ct_event> events_;
    Vec<ct_occupant> occupants_;
    Vec<ct_line_count> line_counts_;
    Vec<ct_zone_count> zone_counts_;
    // Scratch, kept from step to step so that steady state allocates
    // nothing.
    Vec<Live> live_;
    Next next_;
};

} // namespace ctrack

#endif
