// A Result from a render through lesson 05's pipeline: the target's colour
// and depth, the pipeline's counts, the camera it was seen with.
#pragma once

#include "05_perspective/camera.hpp"
#include "05_perspective/pipeline.hpp"
#include "05_perspective/render_target.hpp"
#include "result.hpp"

namespace py_rl {

void take_frame(Result& r, pipeline::ColourTarget& frame, const pipeline::PipelineCounts& counts,
                const pipeline::Camera& camera);

}  // namespace py_rl
