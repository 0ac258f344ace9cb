// A Result from a render through lesson 05's pipeline: the target's colour
// and depth, the pipeline's counts, the camera it was seen with.
#pragma once

#include "05_perspective/camera.hpp"
#include "05_perspective/pipeline.hpp"
#include "05_perspective/render_target.hpp"
#include "result.hpp"

namespace py_rl {

void take_frame(Result& r, perspective::ColourTarget& frame, const perspective::PipelineCounts& counts,
                const perspective::Camera& camera);

}  // namespace py_rl
