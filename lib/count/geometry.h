// The plane geometry of counting: which side of a line a point is, where a
// path crosses it, and simple polygons (their checks, inside, distance).
#ifndef CTRACK_GEOMETRY_H
#define CTRACK_GEOMETRY_H

namespace ctrack {

struct Pt {
    double x, y;
};

// p's signed distance from the line through a and b (a != b), in pixels:
// positive on the right-hand side of a -> b as the image shows it (its y
// axis pointing down), negative on the left.
double signed_distance(Pt a, Pt b, Pt p);

// Where the path p -> q meets the line through a and b, as a fraction of
// the way from a to b (0 at a, 1 at b); p and q are on opposite sides.
double crossing_fraction(Pt a, Pt b, Pt p, Pt q);

// Whether the closed segments a-b and c-d have a point in common.
bool segments_meet(Pt a, Pt b, Pt c, Pt d);

// What is wrong with the polygon v[0..n-1] (n >= 3) for a zone, or null
// when it is simple and has an area: *i and *j then name the corners or
// edges at fault (edge k runs from corner k to corner k + 1).
const char *polygon_fault(const Pt *v, int n, int *i, int *j);

// The polygon's area (positive either way round).
double polygon_area(const Pt *v, int n);

// Whether p is inside the polygon (even-odd rule; a point on an edge may
// go either way).
bool inside_polygon(const Pt *v, int n, Pt p);

// p's distance to the polygon's nearest edge.
double distance_to_edges(const Pt *v, int n, Pt p);

} // namespace ctrack

#endif
