#include "count/geometry.h"

#include <algorithm>
#include <cmath>

namespace ctrack {

namespace {

double cross(Pt o, Pt a, Pt b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

int sign(double v)
{
    return (v > 0) - (v < 0);
}

// Whether p, collinear with a-b, lies on the closed segment a-b.
bool on_segment(Pt a, Pt b, Pt p)
{
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

// Whether p lies on the closed segment a-b.
bool lies_on(Pt a, Pt b, Pt p)
{
    return cross(a, b, p) == 0 && on_segment(a, b, p);
}

double distance_to_segment(Pt a, Pt b, Pt p)
{
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

} // namespace

double signed_distance(Pt a, Pt b, Pt p)
{
    return cross(a, b, p) / std::hypot(b.x - a.x, b.y - a.y);
}

double crossing_fraction(Pt a, Pt b, Pt p, Pt q)
{
    // The point of p -> q on the line, then its place along a -> b.
    const double dp = cross(a, b, p), dq = cross(a, b, q);
    const double s = dp / (dp - dq);
    const Pt m{p.x + s * (q.x - p.x), p.y + s * (q.y - p.y)};
    const double dx = b.x - a.x, dy = b.y - a.y;
    return ((m.x - a.x) * dx + (m.y - a.y) * dy) / (dx * dx + dy * dy);
}

bool segments_meet(Pt a, Pt b, Pt c, Pt d)
{
    const int d1 = sign(cross(c, d, a)), d2 = sign(cross(c, d, b));
    const int d3 = sign(cross(a, b, c)), d4 = sign(cross(a, b, d));
    if (d1 * d2 < 0 && d3 * d4 < 0)
        return true;
    return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) ||
           (d3 == 0 && on_segment(a, b, c)) || (d4 == 0 && on_segment(a, b, d));
}

const char *polygon_fault(const Pt *v, int n, int *i, int *j)
{
    for (int k = 0; k < n; k++) {
        const Pt p = v[k], q = v[(k + 1) % n];
        if (p.x == q.x && p.y == q.y) {
            *i = k;
            *j = (k + 1) % n;
            return "corners coincide";
        }
    }
    for (int k = 0; k < n; k++) {
        const Pt a = v[k], b = v[(k + 1) % n];
        for (int m = k + 1; m < n; m++) {
            const Pt c = v[m], d = v[(m + 1) % n];
            const bool next = m == k + 1, prev = k == 0 && m == n - 1;
            bool meet;
            if (next) // they share b == c: wrong only if one folds back onto the other
                meet = lies_on(a, b, d) || lies_on(c, d, a);
            else if (prev) // they share a == d
                meet = lies_on(a, b, c) || lies_on(c, d, b);
            else
                meet = segments_meet(a, b, c, d);
            if (meet) {
                *i = k;
                *j = m;
                return "edges cross or touch";
            }
        }
    }
    if (polygon_area(v, n) < 1.0) {
        *i = *j = 0;
        return "area under one square pixel";
    }
    return nullptr;
}

double polygon_area(const Pt *v, int n)
{
    double a = 0;
    for (int k = 0; k < n; k++) {
        const Pt p = v[k], q = v[(k + 1) % n];
        a += p.x * q.y - q.x * p.y;
    }
    return std::fabs(a) / 2;
}

bool inside_polygon(const Pt *v, int n, Pt p)
{
    bool in = false;
    for (int k = 0, l = n - 1; k < n; l = k++) {
        if ((v[k].y > p.y) != (v[l].y > p.y) &&
            p.x < (v[l].x - v[k].x) * (p.y - v[k].y) / (v[l].y - v[k].y) + v[k].x)
            in = !in;
    }
    return in;
}

double distance_to_edges(const Pt *v, int n, Pt p)
{
    double d = INFINITY;
    for (int k = 0; k < n; k++)
        d = std::min(d, distance_to_segment(v[k], v[(k + 1) % n], p));
    return d;
}

} // namespace ctrack
