#include "dsp/dsp.h"

namespace ctrack {

void dsp_init(Dsp *dsp, unsigned flags)
{
    convert_dsp_init(dsp, flags);
    background_dsp_init(dsp, flags);
    nnindex_dsp_init(dsp, flags);
    regions_dsp_init(dsp, flags);
}

} // namespace ctrack
