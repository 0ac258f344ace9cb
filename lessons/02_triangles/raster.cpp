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

std::optional<RasterMethod> parse_raster_method(const std::string& text) {
    for (RasterMethod m : kRasterMethods)
        if (text == name(m)) return m;
    return std::nullopt;
}

}  // namespace triangles
