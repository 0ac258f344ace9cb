#include "wireframe.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "viewport.hpp"

namespace lines {

std::size_t draw_wireframe(rl::Image& image, const rl::Mesh& mesh, rl::Rgba colour,
                           LineMethod method) {
    std::set<std::pair<int, int>> drawn;
    for (const rl::Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int i = t.corners[k].position, j = t.corners[(k + 1) % 3].position;
            if (!drawn.insert(std::minmax(i, j)).second) continue;
            const rl::vec3 a =
                orthographic_to_window(mesh.positions[i], image.width(), image.height());
            const rl::vec3 b =
                orthographic_to_window(mesh.positions[j], image.width(), image.height());
            draw_line(image, a.xy(), b.xy(), colour, method);
        }
    return drawn.size();
}

}  // namespace lines
