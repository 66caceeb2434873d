// The floor of the barycenter error (docs/tuning.md, "Boxes fitted to the
// silhouette"): the ground truth's own boxes fitted to the silhouettes of
// the foreground the pixels-alone tracker finds online, all the way
// (fit_box() with follow 1), for eval/eval.py to measure how far the
// annotators' boxes sit from the people's silhouettes. Internal: it links
// the engine itself. Not installed.
//
//   fit-floor VIDEO.y4m GT.txt OUT.txt
//
// OUT holds the fitted ground-truth rows (frame, id, left, top, width,
// height), for the boxes the fit takes: past the model's first second,
// not covered by another person's box by more than a sixth.
#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "pixels/box_fit.h"
#include "pixels_run.h"

namespace {

struct Row {
    int id;
    ctrack::Box box;
};

bool covered(const std::vector<Row> &rows, size_t i)
{
    const ctrack::Box &b = rows[i].box;
    for (size_t j = 0; j < rows.size(); j++) {
        if (j == i)
            continue;
        const ctrack::Box &o = rows[j].box;
        const double ix = std::min(b.left + b.width, o.left + o.width) - std::max(b.left, o.left);
        const double iy = std::min(b.top + b.height, o.top + o.height) - std::max(b.top, o.top);
        if (ix > 0 && iy > 0 && ix * iy > b.width * b.height / 6)
            return true;
    }
    return false;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: fit-floor VIDEO.y4m GT.txt OUT.txt\n");
        return 2;
    }
    std::map<int, std::vector<Row>> gt;
    FILE *g = std::fopen(argv[2], "r");
    if (!g) {
        std::perror(argv[2]);
        return 1;
    }
    double f, id, l, t, w, h, conf;
    char line[512];
    while (std::fgets(line, sizeof line, g))
        if (std::sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &f, &id, &l, &t, &w, &h, &conf) == 7 &&
            conf != 0)
            gt[(int)f].push_back(Row{(int)id, ctrack::Box{l, t, w, h}});
    std::fclose(g);
    FILE *out = std::fopen(argv[3], "w");
    if (!out) {
        std::perror(argv[3]);
        return 1;
    }
    const int status = run_pixels("fit-floor", argv[1], [&](int k, const ctrack::Engine &engine,
                                                             const ct_frame &f) {
        int mw, mh;
        const uint8_t *mask = engine.foreground(&mw, &mh);
        if (!mask || f.timestamp_us < 1000000)
            return;
        std::vector<Row> &rows = gt[k];
        for (size_t i = 0; i < rows.size(); i++) {
            ctrack::Box fitted;
            if (covered(rows, i) ||
                !ctrack::fit_box(mask, mw, mh, engine.working_scale(), rows[i].box, 1.0,
                                 &engine.person_size(), false, &fitted))
                continue;
            std::fprintf(out, "%d,%d,%.2f,%.2f,%.2f,%.2f\n", k, rows[i].id, fitted.left,
                         fitted.top, fitted.width, fitted.height);
        }
    });
    return std::fclose(out) == 0 ? status : 1;
}
