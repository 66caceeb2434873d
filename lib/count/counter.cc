#include "count/counter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "api/error.h"
#include "base/clock.h"

namespace ctrack {

namespace {

// Farther than this from the origin, a point is no pixel of any camera.
constexpr double kMaxCoordinate = 1e6;
constexpr double kMaxHysteresis = 2;

bool point_ok(const ct_point &p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::fabs(p.x) <= kMaxCoordinate &&
           std::fabs(p.y) <= kMaxCoordinate;
}

bool hysteresis_ok(float h)
{
    return std::isfinite(h) && h >= 0 && h <= kMaxHysteresis;
}

int sign(double v)
{
    return (v > 0) - (v < 0);
}

Pt anchor_of(const ct_track &t)
{
    return Pt{t.left + t.width / 2.0, (double)t.top + t.height};
}

} // namespace

int Counter::take_name(const char *name, const char *prefix, size_t index, char *out,
                       char *msg, size_t len) const
{
    char own[CT_NAME_SIZE];
    if (!name || !name[0]) {
        std::snprintf(own, sizeof own, "%s%zu", prefix, index);
        name = own;
    } else if (std::strlen(name) >= CT_NAME_SIZE) {
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "name: %zu bytes; a name has at most %d", std::strlen(name),
                    CT_NAME_SIZE - 1);
    }
    const bool line = prefix[0] == 'l';
    const size_t n = line ? line_counts_.size() : zone_counts_.size();
    for (size_t i = 0; i < n; i++) {
        const char *taken = line ? line_counts_[i].name : zone_counts_[i].name;
        if (std::strcmp(taken, name) == 0)
            return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                        "name: \"%s\" is already %s %zu's", name, line ? "line" : "zone", i);
    }
    std::memset(out, 0, CT_NAME_SIZE);
    std::memcpy(out, name, std::strlen(name));
    return CT_OK;
}

// Each follow's states sit in a row of the per-line and per-zone arrays;
// adding a line or a zone widens every row by one state not known yet.
template <typename S>
static void widen(Vec<S> &states, size_t rows, size_t old_width, S unknown)
{
    Vec<S> wide;
    wide.reserve(rows * (old_width + 1));
    for (size_t r = 0; r < rows; r++) {
        wide.insert(wide.end(), states.begin() + r * old_width,
                    states.begin() + (r + 1) * old_width);
        wide.push_back(unknown);
    }
    states.swap(wide);
}

int Counter::add_line(const ct_line &line, int64_t last_us, int32_t *index, char *msg,
                      size_t len)
{
    if (lines_.size() >= CT_COUNT_MAX_LINES)
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "line: a tracker counts on at most %d lines (CT_COUNT_MAX_LINES)",
                    CT_COUNT_MAX_LINES);
    for (const ct_point *p : {&line.a, &line.b})
        if (!point_ok(*p))
            return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                        "line.%s: (%g, %g) is not a point of an image (finite, within "
                        "%g pixels of the origin)",
                        p == &line.a ? "a" : "b", p->x, p->y, kMaxCoordinate);
    const Pt a{line.a.x, line.a.y}, b{line.b.x, line.b.y};
    if (std::hypot(b.x - a.x, b.y - a.y) < 1)
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "line: (%g, %g) to (%g, %g) is under a pixel long; a line needs two "
                    "end points apart",
                    a.x, a.y, b.x, b.y);
    if (!hysteresis_ok(line.hysteresis))
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "line.hysteresis: %g is not in [0, %g] box heights", line.hysteresis,
                    kMaxHysteresis);
    ct_line_count c = {};
    c.index = (int32_t)lines_.size();
    if (const int st = take_name(line.name, "line", lines_.size(), c.name, msg, len))
        return st;
    // Everything that allocates first; then nothing throws.
    lines_.reserve(lines_.size() + 1);
    line_counts_.reserve(line_counts_.size() + 1);
    Vec<LineState> states = line_states_;
    widen(states, follows_.size(), lines_.size(), LineState{0, Pt{0, 0}});
    lines_.push_back(Line{a, b, line.hysteresis, last_us});
    line_counts_.push_back(c);
    line_states_.swap(states);
    if (index)
        *index = c.index;
    return CT_OK;
}

int Counter::add_zone(const ct_zone &zone, int64_t last_us, int32_t *index, char *msg,
                      size_t len)
{
    if (zones_.size() >= CT_COUNT_MAX_ZONES)
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "zone: a tracker counts in at most %d zones (CT_COUNT_MAX_ZONES)",
                    CT_COUNT_MAX_ZONES);
    if (!zone.points)
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT, "zone.points: NULL pointer");
    const int n = zone.n_points;
    if (n < 3 || n > CT_ZONE_MAX_POINTS)
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "zone.n_points: %d; a zone has 3 to %d corners", n, CT_ZONE_MAX_POINTS);
    Pt v[CT_ZONE_MAX_POINTS];
    for (int k = 0; k < n; k++) {
        if (!point_ok(zone.points[k]))
            return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                        "zone.points[%d]: (%g, %g) is not a point of an image (finite, "
                        "within %g pixels of the origin)",
                        k, zone.points[k].x, zone.points[k].y, kMaxCoordinate);
        v[k] = Pt{zone.points[k].x, zone.points[k].y};
    }
    int i = 0, j = 0;
    if (const char *fault = polygon_fault(v, n, &i, &j))
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "zone.points: not a simple polygon with an area: %s (%d and %d; edge k "
                    "joins points k and k + 1)",
                    fault, i, j);
    if (!hysteresis_ok(zone.hysteresis))
        return fail(msg, len, CT_ERROR_INVALID_ARGUMENT,
                    "zone.hysteresis: %g is not in [0, %g] box heights", zone.hysteresis,
                    kMaxHysteresis);
    ct_zone_count c = {};
    c.index = (int32_t)zones_.size();
    if (const int st = take_name(zone.name, "zone", zones_.size(), c.name, msg, len))
        return st;
    zones_.reserve(zones_.size() + 1);
    zone_counts_.reserve(zone_counts_.size() + 1);
    corners_.reserve(corners_.size() + n);
    Vec<ZoneState> states = zone_states_;
    widen(states, follows_.size(), zones_.size(), ZoneState{-1, 0});
    zones_.push_back(Zone{(int)corners_.size(), n, zone.hysteresis, last_us});
    corners_.insert(corners_.end(), v, v + n);
    zone_counts_.push_back(c);
    zone_states_.swap(states);
    if (index)
        *index = c.index;
    return CT_OK;
}

void Counter::gather(const Vec<Track> &tracks, const Vec<ct_track> &reported)
{
    live_.clear();
    live_.reserve(tracks.size());
    for (const Track &t : tracks) {
        if (t.state == CT_TRACK_TENTATIVE)
            continue;
        Live l = {};
        l.id = t.id;
        l.start = Pt{t.start_x, t.start_bottom};
        l.start_us = t.start_us;
        // reported is in increasing id order.
        auto r = std::lower_bound(reported.begin(), reported.end(), t.id,
                                  [](const ct_track &o, uint64_t id) { return o.id < id; });
        if (t.state == CT_TRACK_CONFIRMED && r != reported.end() && r->id == t.id) {
            l.seen = true;
            l.anchor = anchor_of(*r);
            l.height = r->height;
        }
        live_.push_back(l);
    }
    std::sort(live_.begin(), live_.end(), [](const Live &a, const Live &b) { return a.id < b.id; });
}

void Counter::reserve(Next &n) const
{
    const size_t follows = live_.size(), nl = lines_.size(), nz = zones_.size();
    n.follows.clear();
    n.lines.clear();
    n.zones.clear();
    n.events.clear();
    n.occupants.clear();
    n.follows.reserve(follows);
    n.lines.reserve(follows * nl);
    n.zones.reserve(follows * nz);
    // At most one event a line and a zone for each follow, live or ended.
    n.events.reserve((follows + follows_.size()) * (nl + nz));
    n.occupants.reserve(follows * nz);
    n.line_counts.assign(line_counts_.begin(), line_counts_.end());
    n.zone_counts.assign(zone_counts_.begin(), zone_counts_.end());
}

void Counter::emit(Next &n, int kind, int index, uint64_t id, int64_t t_us, Pt at)
{
    ct_event e = {};
    e.kind = kind;
    e.index = index;
    e.track_id = id;
    e.timestamp_us = t_us;
    e.x = (float)at.x;
    e.y = (float)at.y;
    n.events.push_back(e);
}

void Counter::start(Next &n, const Live &l) const
{
    n.follows.push_back(Follow{l.id, l.start});
    // A line or zone added since the track started knows its side from
    // its next box only.
    for (const Line &line : lines_) {
        const int s = sign(signed_distance(line.a, line.b, l.start));
        n.lines.push_back(LineState{l.start_us > line.added_us ? s : 0, l.start});
    }
    for (const Zone &z : zones_) {
        const bool in = inside_polygon(&corners_[z.first], z.n, l.start);
        n.zones.push_back(ZoneState{l.start_us > z.added_us ? (in ? 1 : 0) : -1, l.start_us});
    }
}

void Counter::observe(Next &n, size_t f, const Live &l, int64_t t_us) const
{
    if (!l.seen)
        return;
    const Pt p = l.anchor;
    n.follows[f].last = p;
    for (size_t i = 0; i < lines_.size(); i++) {
        const Line &line = lines_[i];
        LineState &st = n.lines[f * lines_.size() + i];
        const double d = signed_distance(line.a, line.b, p);
        const int s = sign(d);
        if (st.side == 0 || s == st.side) {
            // Where it stands on its side: a later crossing runs from here.
            if (s != 0)
                st = LineState{s, p};
            continue;
        }
        if (s == 0 || std::fabs(d) < line.hysteresis * l.height)
            continue; // not yet past the line by the hysteresis
        const double at = crossing_fraction(line.a, line.b, st.on_side, p);
        if (at >= 0 && at <= 1) { // through the segment, not around its ends
            const bool in = s > 0;
            emit(n, in ? CT_EVENT_LINE_IN : CT_EVENT_LINE_OUT, (int)i, l.id, t_us, p);
            (in ? n.line_counts[i].in : n.line_counts[i].out)++;
        }
        st = LineState{s, p};
    }
    for (size_t i = 0; i < zones_.size(); i++) {
        const Zone &z = zones_[i];
        ZoneState &st = n.zones[f * zones_.size() + i];
        const bool in = inside_polygon(&corners_[z.first], z.n, p);
        if (st.inside < 0) {
            st = ZoneState{in ? 1 : 0, t_us};
            continue;
        }
        if (in == (st.inside == 1) ||
            distance_to_edges(&corners_[z.first], z.n, p) < z.hysteresis * l.height)
            continue;
        if (in) {
            emit(n, CT_EVENT_ZONE_ENTER, (int)i, l.id, t_us, p);
            n.zone_counts[i].entered++;
        } else {
            emit(n, CT_EVENT_ZONE_EXIT, (int)i, l.id, t_us, p);
            n.events.back().dwell = elapsed_s(t_us, st.since_us);
            n.zone_counts[i].exited++;
        }
        st = ZoneState{in ? 1 : 0, t_us};
    }
}

void Counter::end(Next &n, size_t old, int64_t t_us) const
{
    for (size_t i = 0; i < zones_.size(); i++) {
        const ZoneState &st = zone_states_[old * zones_.size() + i];
        if (st.inside != 1)
            continue;
        emit(n, CT_EVENT_ZONE_EXIT, (int)i, follows_[old].id, t_us, follows_[old].last);
        ct_event &e = n.events.back();
        e.dwell = elapsed_s(t_us, st.since_us);
        e.ended = 1;
        n.zone_counts[i].exited++;
    }
}

void Counter::list_occupants(Next &n, int64_t t_us) const
{
    for (size_t i = 0; i < zones_.size(); i++) {
        int32_t inside = 0;
        for (size_t f = 0; f < n.follows.size(); f++) {
            const ZoneState &st = n.zones[f * zones_.size() + i];
            if (st.inside != 1)
                continue;
            n.occupants.push_back(ct_occupant{(int32_t)i, n.follows[f].id,
                                              elapsed_s(t_us, st.since_us)});
            inside++;
        }
        n.zone_counts[i].inside = inside;
    }
}

void Counter::step(int64_t t_us, const Vec<Track> &tracks, const Vec<ct_track> &reported)
{
    if (lines_.empty() && zones_.empty()) {
        events_.clear();
        return;
    }
    gather(tracks, reported);
    Next &n = next_;
    reserve(n);
    // Nothing below allocates: every vector has the room it needs.
    const size_t nl = lines_.size(), nz = zones_.size();
    size_t old = 0;
    for (const Live &l : live_) {
        for (; old < follows_.size() && follows_[old].id < l.id; old++)
            end(n, old, t_us);
        const size_t f = n.follows.size();
        if (old < follows_.size() && follows_[old].id == l.id) {
            n.follows.push_back(follows_[old]);
            n.lines.insert(n.lines.end(), line_states_.begin() + old * nl,
                           line_states_.begin() + (old + 1) * nl);
            n.zones.insert(n.zones.end(), zone_states_.begin() + old * nz,
                           zone_states_.begin() + (old + 1) * nz);
            old++;
        } else if (l.seen) { // followed from when it is first seen
            start(n, l);
        } else {
            continue;
        }
        observe(n, f, l, t_us);
    }
    for (; old < follows_.size(); old++)
        end(n, old, t_us);
    list_occupants(n, t_us);
    follows_.swap(n.follows);
    line_states_.swap(n.lines);
    zone_states_.swap(n.zones);
    events_.swap(n.events);
    occupants_.swap(n.occupants);
    line_counts_.swap(n.line_counts);
    zone_counts_.swap(n.zone_counts);
}

void Counter::forget_tracks() noexcept
{
    follows_.clear();
    line_states_.clear();
    zone_states_.clear();
    events_.clear();
    occupants_.clear();
    for (ct_zone_count &c : zone_counts_)
        c.inside = 0;
    // Every track from now on is new to every line and zone.
    for (Line &l : lines_)
        l.added_us = INT64_MIN;
    for (Zone &z : zones_)
        z.added_us = INT64_MIN;
}

size_t Counter::memory_bytes() const
{
    size_t b = lines_.capacity() * sizeof(Line) + zones_.capacity() * sizeof(Zone) +
               corners_.capacity() * sizeof(Pt) + live_.capacity() * sizeof(Live);
    for (const auto *s : {&follows_, &next_.follows})
        b += s->capacity() * sizeof(Follow);
    for (const auto *s : {&line_states_, &next_.lines})
        b += s->capacity() * sizeof(LineState);
    for (const auto *s : {&zone_states_, &next_.zones})
        b += s->capacity() * sizeof(ZoneState);
    for (const auto *s : {&events_, &next_.events})
        b += s->capacity() * sizeof(ct_event);
    for (const auto *s : {&occupants_, &next_.occupants})
        b += s->capacity() * sizeof(ct_occupant);
    b += (line_counts_.capacity() + next_.line_counts.capacity()) * sizeof(ct_line_count);
    b += (zone_counts_.capacity() + next_.zone_counts.capacity()) * sizeof(ct_zone_count);
    return b;
}

} // namespace ctrack
