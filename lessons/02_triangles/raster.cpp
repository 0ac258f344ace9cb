#include "raster.hpp"

namespace triangles {

const char* name(RasterMethod method) {
    switch (method) {
        case RasterMethod::scanline:
            return "scanline";
        case RasterMethod::bbox:
            return "bbox";
        case RasterMethod::edge:
            return "edge";
    }
    return "?";
}

}  // namespace triangles
