// Scene-like frames for fuzz_feed: a 320x240 textured ground with people
// walking on it (a head, a torso, legs in stride), at the sizes a camera's
// perspective gives them, alone, side by side, crossing, in groups, some in
// clothes the colour of the ground (a blob in fragments), some stopping; and
// objects that are no person (a board moved once). The fuzzer's bytes write
// the script; the frames follow it, so that the background model, the blob
// merging and group splitting and the people's size all meet what they meet
// on a real street.
#ifndef CT_FUZZ_SCENE_H
#define CT_FUZZ_SCENE_H

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace scene {

constexpr int kWidth = 320, kHeight = 240;

struct Figure {
    double x0, feet, speed, height; // pixels, pixels a frame
    int start, stop;                // frames: it appears, it stops
    uint8_t luma, u, v;
    bool person;                    // else a board: a filled rectangle
    bool torso_like_ground;         // the torso in the ground's colour
    bool loops;                     // it leaves on one side, comes back on the other
};

struct Script {
    std::vector<Figure> figures;
    double slope, intercept; // a person's height against the row of their feet
    int light_step;          // a frame from which the light is brighter (-1: none)
};

inline Script read_script(FuzzedDataProvider &in)
{
    Script s;
    // People 40 to 120 pixels tall, taller lower in the picture.
    s.slope = in.ConsumeFloatingPointInRange<double>(0.2, 0.6);
    s.intercept = in.ConsumeFloatingPointInRange<double>(-20.0, 20.0);
    s.light_step = in.ConsumeIntegralInRange<int>(0, 3) == 0
                       ? in.ConsumeIntegralInRange<int>(5, 120)
                       : -1;
    // Now and then a procession: people one behind the other along a row,
    // at one pace, apart (many boxes of one size: the size model's bands
    // fill and halve their counts).
    if (in.ConsumeIntegralInRange<int>(0, 7) == 0) {
        const double feet = in.ConsumeFloatingPointInRange<double>(150.0, 230.0);
        const double speed = in.ConsumeFloatingPointInRange<double>(1.0, 3.0);
        for (int k = 0; k < 7; k++) {
            Figure f{};
            f.feet = feet;
            f.height = std::max(20.0, s.slope * feet + s.intercept);
            f.person = true;
            f.speed = speed;
            f.x0 = -30.0 + k * 0.8 * f.height;
            f.stop = 1 << 30;
            f.luma = (uint8_t)(20 + 25 * k);
            f.u = f.v = 128;
            f.loops = true;
            s.figures.push_back(f);
        }
        return s;
    }
    const int n = in.ConsumeIntegralInRange<int>(1, 7);
    for (int k = 0; k < n; k++) {
        Figure f{};
        const int kind = in.ConsumeIntegralInRange<int>(0, 7);
        f.feet = in.ConsumeFloatingPointInRange<double>(140.0, 236.0);
        f.height = std::max(20.0, s.slope * f.feet + s.intercept);
        f.person = kind != 0;
        f.speed = in.ConsumeFloatingPointInRange<double>(-4.0, 4.0);
        f.x0 = in.ConsumeFloatingPointInRange<double>(-40.0, kWidth + 40.0);
        if (kind == 1 && k > 0) { // beside the one before, at its pace: a pair
            const Figure &o = s.figures.back();
            f.feet = o.feet + in.ConsumeFloatingPointInRange<double>(-6.0, 6.0);
            f.height = o.height * in.ConsumeFloatingPointInRange<double>(0.9, 1.1);
            f.speed = o.speed;
            f.x0 = o.x0 + o.height * in.ConsumeFloatingPointInRange<double>(0.15, 0.45);
        }
        f.start = in.ConsumeBool() ? 0 : in.ConsumeIntegralInRange<int>(0, 60);
        f.stop = in.ConsumeIntegralInRange<int>(0, 3) == 0 ? f.start +
                                                                 in.ConsumeIntegralInRange<int>(0, 80)
                                                           : 1 << 30;
        f.luma = in.ConsumeIntegralInRange<uint8_t>(0, 255);
        f.u = in.ConsumeIntegralInRange<uint8_t>(90, 170);
        f.v = in.ConsumeIntegralInRange<uint8_t>(90, 170);
        f.torso_like_ground = in.ConsumeIntegralInRange<int>(0, 5) == 0;
        s.figures.push_back(f);
    }
    return s;
}

// The ground: a texture with edges (paving, a kerb), the same every frame.
inline uint8_t ground(int x, int y)
{
    return (uint8_t)(70 + ((x / 16 + y / 12) % 2) * 12 + (y > 120 ? 20 : 0) + ((x * 7 + y * 3) % 5));
}

// Whether (x, y) is on figure f at frame t (its feet at f.feet, its centre
// at cx).
inline bool covers(const Figure &f, double cx, int t, double x, double y, bool *torso)
{
    const double h = f.height, top = f.feet - h, dy = y - top, dx = x - cx;
    *torso = false;
    if (dy < 0 || dy > h)
        return false;
    if (!f.person)
        return std::fabs(dx) < 0.3 * h && dy > 0.2 * h;
    const double head = 0.06 * h;
    if (dy < 2 * head)
        return dx * dx + (dy - head) * (dy - head) < head * head;
    if (dy < 0.55 * h) { // shoulders, torso and arms
        *torso = std::fabs(dx) < 0.13 * h;
        return std::fabs(dx) < (dy < 0.2 * h ? 0.11 : 0.16) * h;
    }
    // Legs in stride: apart, then together, every 16 frames.
    const double spread = 0.1 * h * std::fabs(std::sin(t * 3.14159 / 8)) * (dy - 0.55 * h) / (0.45 * h);
    const double leg = 0.05 * h;
    return std::fabs(dx - spread) < leg || std::fabs(dx + spread) < leg;
}

// Frame t of the script into I420 planes of kWidth x kHeight (y, u, v
// tight), and the boxes of the figures in view (left, top, width, height).
inline void render(const Script &s, int t, uint8_t *y, uint8_t *u, uint8_t *v,
                   std::vector<float> *boxes)
{
    const int lift = s.light_step >= 0 && t >= s.light_step ? 25 : 0;
    for (int r = 0; r < kHeight; r++)
        for (int c = 0; c < kWidth; c++)
            y[r * kWidth + c] = (uint8_t)std::min(255, ground(c, r) + lift);
    for (int i = 0; i < kWidth / 2 * kHeight / 2; i++)
        u[i] = v[i] = 128;
    boxes->clear();
    // Farther figures first: a nearer one hides them.
    std::vector<const Figure *> order;
    for (const Figure &f : s.figures)
        if (t >= f.start)
            order.push_back(&f);
    std::sort(order.begin(), order.end(),
              [](const Figure *a, const Figure *b) { return a->feet < b->feet; });
    for (const Figure *f : order) {
        const int moving = std::min(t, f->stop) - f->start;
        double cx = f->x0 + f->speed * moving;
        if (f->loops) // a walk round a block: back in on the left
            cx = std::fmod(cx + 40.0, kWidth + 80.0) - 40.0;
        const int x0 = std::max(0, (int)(cx - 0.35 * f->height)),
                  x1 = std::min(kWidth, (int)(cx + 0.35 * f->height) + 1);
        const int y0 = std::max(0, (int)(f->feet - f->height)),
                  y1 = std::min(kHeight, (int)f->feet + 1);
        if (x0 >= x1 || y0 >= y1)
            continue;
        boxes->insert(boxes->end(), {(float)(cx - 0.17 * f->height),
                                     (float)(f->feet - f->height), (float)(0.34 * f->height),
                                     (float)f->height});
        for (int r = y0; r < y1; r++)
            for (int c = x0; c < x1; c++) {
                bool torso;
                if (!covers(*f, cx, t, c + 0.5, r + 0.5, &torso))
                    continue;
                y[r * kWidth + c] = torso && f->torso_like_ground
                                        ? (uint8_t)std::min(255, ground(c, r) + lift)
                                        : f->luma;
                if (!(torso && f->torso_like_ground)) {
                    u[(r / 2) * (kWidth / 2) + c / 2] = f->u;
                    v[(r / 2) * (kWidth / 2) + c / 2] = f->v;
                }
            }
    }
}

} // namespace scene

#endif
