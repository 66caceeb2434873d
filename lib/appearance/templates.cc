#include "appearance/templates.h"

#include "base/clock.h"

namespace ctrack {

namespace {

// A track's appearance template is remade from its detection at most this
// often (seconds), when nothing occludes it.
constexpr double kTemplateRefresh = 0.5;

constexpr size_t kDescFloats = (size_t)kPoints * kDescDim;

} // namespace

void TemplateBank::begin(const Planes &img, const ct_detection *dets, size_t n,
                         Counters *counters)
{
    img_ = img;
    dets_ = dets;
    counters_ = counters;
    desc_of_.assign(n, -1);
    det_desc_.clear();
}

const float *TemplateBank::descriptors(int det)
{
    int &slot = desc_of_[(size_t)det];
    if (slot < 0) {
        slot = (int)(det_desc_.size() / kDescFloats);
        det_desc_.resize(det_desc_.size() + kDescFloats);
        const ct_detection &d = dets_[det];
        describer_.describe(img_, d.left, d.top, d.width, d.height,
                            &det_desc_[(size_t)slot * kDescFloats]);
    }
    return &det_desc_[(size_t)slot * kDescFloats];
}

double TemplateBank::similarity(const Track &t, int det)
{
    if (t.tmpl < 0)
        return 1.0;
    counters_->ddis_runs++;
    return ddis_.ddis(templates_[(size_t)t.tmpl], descriptors(det));
}

void TemplateBank::learn(Vec<Track> &tracks, const Vec<Track> &saved, const Vec<Track> *kept,
                         int64_t t_us)
{
    slot_used_.assign(templates_.size(), 0);
    const Vec<Track> *const all[] = {&tracks, &saved, kept};
    for (const Vec<Track> *v : all)
        if (v)
            for (const Track &t : *v)
                if (t.tmpl >= 0)
                    slot_used_[t.tmpl] = 1;
    size_t slot = 0;
    for (size_t i = 0; i < tracks.size(); i++) {
        Track &t = tracks[i];
        if (t.state != CT_TRACK_CONFIRMED || t.det_index < 0 || t.last_update_us != t_us)
            continue;
        if (t.tmpl >= 0 &&
            (elapsed_s(t_us, t.tmpl_us) < kTemplateRefresh || occluded(tracks, i)))
            continue;
        while (slot < slot_used_.size() && slot_used_[slot])
            slot++;
        if (slot == templates_.size()) {
            templates_.emplace_back();
            slot_used_.push_back(0);
        }
        templates_[slot].build(descriptors(t.det_index));
        slot_used_[slot] = 1;
        t.tmpl = (int)slot;
        t.tmpl_us = t_us;
        counters_->template_builds++;
    }
}

size_t TemplateBank::memory_bytes() const
{
    size_t b = templates_.capacity() * sizeof(Template) + slot_used_.capacity() +
               desc_of_.capacity() * sizeof(int) + det_desc_.capacity() * sizeof(float) +
               describer_.memory_bytes();
    for (const Template &tp : templates_)
        b += tp.desc.capacity() * sizeof(float) + tp.index.memory_bytes();
    return b;
}

} // namespace ctrack
