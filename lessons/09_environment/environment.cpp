#include "environment.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "rasterlab/image_io.hpp"

namespace environment {

namespace {

// A loaded map's texels as light: finite, 0 or more and at most
// kMaxRadiance; the rest set to 0. (RGBE cannot store NaN or a negative
// value, but its largest exponent gives 10^38, which a filter's sum of four
// texels turns into infinity.)
rl::HdrImage cleaned(rl::HdrImage image, const std::string& path,
                     std::vector<std::string>& warnings) {
    long bad = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            rl::vec4 t = image.get(x, y);
            bool changed = false;
            for (float* c : {&t.x, &t.y, &t.z})
                if (!(*c >= 0 && *c <= kMaxRadiance)) *c = 0, changed = true;
            if (changed) {
                ++bad;
                image.set(x, y, t);
            }
        }
    if (bad > 0)
        warnings.push_back(path + ": " + std::to_string(bad) +
                           " texels were negative, not a number or above " +
                           std::to_string(static_cast<long long>(kMaxRadiance)) + "; set to 0");
    return image;
}

// The largest .hdr file a program reads (see make_environment).
const rl::ImageCap& file_cap() {
    static const rl::ImageCap cap{2 * kMaxMapSize, kMaxMapSize,
                                  "lesson 09's cap on a lat-long map (as high as its largest "
                                  "map, twice as wide)"};
    return cap;
}

}  // namespace

double Environment::texel_radians() const {
    return cube_ ? 0.5 * std::numbers::pi / cube_->size() : std::numbers::pi / latlong_->height();
}

float Environment::level_for(double radians) const {
    const double level = std::log2(radians / texel_radians());
    return level > 0 && std::isfinite(level) ? static_cast<float>(level) : 0.0f;
}

rl::vec3 Environment::blurred(rl::vec3 direction, float level) const {
    return cube_ ? cube_->sample(direction, MapFilter::trilinear, level)
                 : latlong_->sample(direction, MapFilter::trilinear, level);
}

Environment make_environment(const EnvironmentOptions& options,
                             std::vector<std::string>& warnings) {
    if (options.size < 1 || options.size > kMaxMapSize)
        throw std::invalid_argument("--map-size: " + std::to_string(options.size) +
                                    " is outside 1 to " + std::to_string(kMaxMapSize));
    if (const std::optional<Analytic> which = rl::from_name(options.source, kAnalytics)) {
        const int samples = texel_samples(options.size);
        if (options.layout == Layout::cube)
            return Environment(cube_map(*which, options.size, samples), options.filter);
        return Environment(latlong_map(*which, options.size, samples), options.filter);
    }
    LatLongMap file(
        cleaned(rl::load_hdr_image(options.source, file_cap()), options.source, warnings));
    if (options.layout == Layout::latlong) return Environment(std::move(file), options.filter);
    return Environment(
        cube_map(
            [&](rl::dvec3 d) {
                return rl::cast<double>(file.sample(rl::cast<float>(d), MapFilter::bilinear));
            },
            options.size, 1),
        options.filter);
}

}  // namespace environment
