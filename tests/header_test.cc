// The public header compiles alone as C++.
#include "ctrack/ctrack.h"

int main()
{
    ct_config cfg;
    return ct_config_default(&cfg, sizeof cfg) == CT_OK ? 0 : 1;
}
