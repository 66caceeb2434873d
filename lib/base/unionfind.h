// Union-find over indices: parent[i] == i at a root.
#ifndef CTRACK_UNIONFIND_H
#define CTRACK_UNIONFIND_H

#include "base/memory.h"

namespace ctrack {

// The root of x's set, halving the path on the way.
inline int find_root(Vec<int> &parent, int x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

} // namespace ctrack

#endif
