#include "mot.h"

void mot_write_tracks(FILE *out, long long frame, const ct_track *tracks, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const ct_track *t = &tracks[i];
        fprintf(out, "%lld,%llu,%.2f,%.2f,%.2f,%.2f,%.3f,-1,-1,-1\n", frame,
                (unsigned long long)t->id, t->left, t->top, t->width, t->height,
                t->confidence);
    }
}

void mot_write_candidates_header(FILE *out)
{
    fprintf(out, "# frame,left,top,width,height,score,yes,voters,head,neck,shoulders,"
                 "chest,back,abdomen,buttocks,upper_limbs,lower_limbs,fill,top_width\n");
}

void mot_write_candidates(FILE *out, long long frame, const ct_candidate *cands, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const ct_candidate *c = &cands[i];
        fprintf(out, "%lld,%.0f,%.0f,%.0f,%.0f,%.3f,%d,%d", frame, c->left, c->top, c->width,
                c->height, c->score, (int)c->votes_yes, (int)c->voters);
        for (int g = 0; g < CT_REGIONS; g++)
            fprintf(out, ",%.4f", c->region_distance[g]);
        fprintf(out, ",%.3f,%.3f\n", c->fill, c->top_width);
    }
}
