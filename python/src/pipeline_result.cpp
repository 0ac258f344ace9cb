#include "pipeline_result.hpp"

namespace py_rl {

void take_frame(Result& r, pipeline::ColourTarget& frame, const pipeline::PipelineCounts& counts,
                const pipeline::Camera& camera) {
    r.colour = std::move(frame.colour());
    if (const rl::FloatImage* depth = frame.depth(); depth && depth->width() == r.colour.width())
        r.depth = std::move(*depth);
    r.count("objects_culled", counts.objects_culled);
    r.count("faces", counts.faces);
    r.count("culled", counts.culled);
    r.count("clipped", counts.clipped);
    r.count("outside", counts.outside);
    r.count("drawn", counts.drawn);
    r.count("refused", counts.refused);
    r.count("fragments", counts.shaded);
    const auto point = [](rl::vec3 p) -> std::vector<double> { return {p.x, p.y, p.z}; };
    r.count("eye", point(camera.eye));  // the camera as framed: what the program prints
    r.count("target", point(camera.target));
    r.count("near", static_cast<double>(camera.near));
    r.count("far", static_cast<double>(camera.far));
}

}  // namespace py_rl
