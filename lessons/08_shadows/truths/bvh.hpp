// A bounding volume hierarchy over world triangles, in double: the lab's
// ray caster (its ground truth, not the renderer). Each node holds the box
// around its triangles; a ray visits only the nodes whose boxes it crosses,
// so a ray costs about log(n) box tests instead of n triangle tests. Built
// by splitting each node's triangles at the median of their centres along
// the box's longest side, down to leaves of at most four.
//
//   const shadows::Bvh bvh(triangles);
//   const shadows::RayHit hit = bvh.nearest(origin, direction, 0, 1e30);
#pragma once

#include <limits>
#include <vector>

#include "05_perspective/truths/ray_truth.hpp"

namespace shadows {

struct RayHit {
    int triangle = -1;  // index into the triangles given, -1 for none
    double t = std::numeric_limits<double>::infinity();
};

class Bvh {
  public:
    explicit Bvh(std::vector<pipeline::WorldTriangle> triangles);

    // The nearest triangle the ray origin + t d meets with t in (t_min, t_max).
    RayHit nearest(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const;
    // Whether any triangle meets it there (a shadow ray: stops at the first).
    bool any(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const;

    const std::vector<pipeline::WorldTriangle>& triangles() const { return triangles_; }

  private:
    struct Node {
        rl::dvec3 low, high;
        int first = 0,
            count = 0;  // a leaf's triangles; an inner node's children are first, first + 1
    };
    template <bool kAny>
    RayHit trace(rl::dvec3 origin, rl::dvec3 d, double t_min, double t_max) const;
    std::vector<pipeline::WorldTriangle> triangles_;  // as given
    std::vector<int> order_;                          // triangle indices, grouped by leaf
    std::vector<Node> nodes_;
};

}  // namespace shadows
