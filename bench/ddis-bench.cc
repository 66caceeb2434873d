// ddis-bench: the cost of one DDIS (a track's template against a
// candidate) and of one template build, at PETS09-S2L1 box sizes with the
// default template (6 x 12 points of 11 numbers), on the real crossing clips
// of tests/data/pets09-crops, with the library's search of all pairs and
// with FLANN's kd-tree; the heap allocations each makes (FLANN's
// KDTreeSingleIndex allocates in findNeighbors and in buildIndex), and how
// many DDIS values the two searches give differently.
//   ddis-bench [--json FILE] DATA_DIR (tests/data)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "alloc_count.h"
#include "appearance/appearance.h"
#include "video.h"

using namespace ctrack;
using clk = std::chrono::steady_clock;

int main(int argc, char **argv)
{
    const char *json = nullptr, *data = nullptr;
    for (int i = 1; i < argc; i++) {
        if (!std::strcmp(argv[i], "--json") && i + 1 < argc)
            json = argv[++i];
        else
            data = argv[i];
    }
    if (!data) {
        std::fprintf(stderr, "usage: ddis-bench [--json FILE] DATA_DIR\n");
        return 2;
    }
    std::string dir = std::string(data) + "/pets09-crops/";
    FILE *f = std::fopen((dir + "crossings.csv").c_str(), "r");
    if (!f) {
        std::perror((dir + "crossings.csv").c_str());
        return 1;
    }
    // The descriptors of every person box of every clip.
    std::vector<std::vector<float>> desc;
    double heights = 0;
    char line[1024];
    while (std::fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        char name[128];
        int frame;
        double b[16];
        if (std::sscanf(line, "%127[^,],%d,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf",
                        name, &frame, b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6, b + 7, b + 8, b + 9,
                        b + 10, b + 11, b + 12, b + 13, b + 14, b + 15) != 18)
            continue;
        video_params ip = {0, 0, CT_FORMAT_I420};
        video_input *in = nullptr;
        video_info info;
        char err[256];
        if (video_open((dir + name + ".y4m").c_str(), &ip, &in, &info, err, sizeof err) < 0) {
            std::fprintf(stderr, "ddis-bench: %s\n", err);
            return 1;
        }
        for (int k = 0; k < 2; k++) {
            ct_frame fr;
            if (video_read(in, &fr, err, sizeof err) != 1)
                return 1;
            Planes p;
            p.width = fr.width;
            p.height = fr.height;
            p.y = fr.planes[0];
            p.u = fr.planes[1];
            p.v = fr.planes[2];
            p.y_stride = fr.strides[0];
            p.u_stride = fr.strides[1];
            p.v_stride = fr.strides[2];
            p.color = true;
            for (int person = 0; person < 2; person++) {
                const double *x = b + (k * 2 + person) * 4;
                desc.emplace_back((size_t)kPoints * kDescDim);
                describe(p, x[0], x[1], x[2], x[3], desc.back().data());
                heights += x[3];
            }
        }
        video_close(in);
    }
    std::fclose(f);
    const size_t n = desc.size();

    // Each search: the appearance library's own (all pairs at kPoints) and
    // FLANN's kd-tree on the same templates.
    struct Figures {
        double build_us, build_allocs, ddis_us, ddis_allocs;
        std::vector<double> values;
    };
    auto measure = [&](bool tree) {
        Figures fig;
        std::vector<Template> templates(n);
        Ddis ddis;
        // Builds: every box's template, several rounds.
        const int rounds = 200;
        unsigned long long a0 = ct_allocations;
        auto t0 = clk::now();
        for (int r = 0; r < rounds; r++)
            for (size_t i = 0; i < n; i++)
                templates[i].build(desc[i].data(), tree);
        fig.build_us = std::chrono::duration<double, std::micro>(clk::now() - t0).count() /
                       (rounds * n);
        fig.build_allocs = (double)(ct_allocations - a0) / (rounds * n);
        // DDIS: every template against every box.
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++)
                fig.values.push_back(ddis.ddis(templates[i], desc[j].data()));
        volatile double sink = 0;
        const int drounds = 20;
        a0 = ct_allocations;
        t0 = clk::now();
        for (int r = 0; r < drounds; r++)
            for (size_t i = 0; i < n; i++)
                for (size_t j = 0; j < n; j++)
                    sink = sink + ddis.ddis(templates[i], desc[j].data());
        const double calls = (double)drounds * n * n;
        fig.ddis_us = std::chrono::duration<double, std::micro>(clk::now() - t0).count() / calls;
        fig.ddis_allocs = (double)(ct_allocations - a0) / calls;
        return fig;
    };
    const Figures all = measure(false), tree = measure(true);
    size_t differ = 0;
    for (size_t k = 0; k < all.values.size(); k++)
        differ += all.values[k] != tree.values[k];

    std::printf("DDIS at PETS09-S2L1 box sizes (mean height %.0f px), template of %d x %d points "
                "of %d numbers, %zu boxes:\n", heights / n, kGridX, kGridY, kDescDim, n);
    std::printf("  search                     one DDIS              one template build\n");
    std::printf("  all pairs (the default)  %7.2f us %5.1f allocs  %6.2f us %5.1f allocs\n",
                all.ddis_us, all.ddis_allocs, all.build_us, all.build_allocs);
    std::printf("  FLANN kd-tree            %7.2f us %5.1f allocs  %6.2f us %5.1f allocs\n",
                tree.ddis_us, tree.ddis_allocs, tree.build_us, tree.build_allocs);
    std::printf("  all pairs against FLANN: %.2fx the speed of a DDIS; %zu of %zu DDIS values "
                "differ\n", tree.ddis_us / all.ddis_us, differ, all.values.size());
    const double ddis_us = all.ddis_us, ddis_allocs = all.ddis_allocs;
    const double build_us = all.build_us, build_allocs = all.build_allocs;
    if (json) {
        FILE *o = std::fopen(json, "w");
        if (!o)
            return 1;
        std::fprintf(o, "{\"ddis_us\": %.4f, \"ddis_allocs\": %.2f, \"build_us\": %.4f, "
                        "\"build_allocs\": %.2f, \"points\": %d, \"dims\": %d, "
                        "\"mean_box_height\": %.1f, \"flann_ddis_us\": %.4f, "
                        "\"flann_ddis_allocs\": %.2f, \"flann_build_us\": %.4f, "
                        "\"flann_build_allocs\": %.2f, \"ddis_values\": %zu, "
                        "\"ddis_values_differing\": %zu}\n",
                     ddis_us, ddis_allocs, build_us, build_allocs, kPoints, kDescDim, heights / n,
                     tree.ddis_us, tree.ddis_allocs, tree.build_us, tree.build_allocs,
                     all.values.size(), differ);
        std::fclose(o);
    }
    return 0;
}
