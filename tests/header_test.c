/* The public header compiles alone, as strict C99 (and, from
 * header_test.cc, as C++). */
#include "ctrack/ctrack.h"

int main(void)
{
    ct_config cfg;
    return ct_config_default(&cfg, sizeof cfg) == CT_OK ? 0 : 1;
}
