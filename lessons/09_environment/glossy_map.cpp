#include "glossy_map.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "brdf.hpp"
#include "sphere_sampling.hpp"

namespace environment {

// [doc:prefilter]
std::vector<LobeSample> ggx_lobe(const Environment& environment, double roughness, int samples) {
    const double alpha = ggx_alpha(std::max(roughness, 1e-3));
    const auto count = static_cast<std::uint32_t>(std::max(samples, 1));
    // The solid angle of one texel of level 0 (at its face's centre).
    const double texel = environment.texel_radians() * environment.texel_radians();
    std::vector<LobeSample> lobe;
    for (std::uint32_t i = 0; i < count; ++i) {
        const rl::dvec3 h = ggx_half_vector(hammersley(i, count), alpha);
        const double l_z = 2 * h.z * h.z - 1;  // l = reflect(-v, h) with v = n = +z
        if (l_z <= 0) continue;
        // With v = n the pdf of l is D(h) / 4; each sample stands for
        // 1 / (count pdf) steradians: read the level whose texels are that big.
        const double pdf = ggx_distribution(h.z, alpha) / 4;
        const double level = 0.5 * std::log2(1 / (count * pdf * texel));
        lobe.push_back(
            {{2 * h.z * h.x, 2 * h.z * h.y, l_z}, static_cast<float>(std::max(level, 0.0))});
    }
    return lobe;
}

rl::vec3 prefiltered_radiance(const Environment& environment, rl::dvec3 r,
                              const std::vector<LobeSample>& lobe) {
    const Frame frame(r);
    rl::dvec3 sum{0, 0, 0};
    double weight = 0;
    for (const LobeSample& s : lobe) {
        // Each reflected direction weighted by n.l (its z about r).
        sum += rl::cast<double>(
                   environment.blurred(rl::cast<float>(frame.to_world(s.direction)), s.level)) *
               s.direction.z;
        weight += s.direction.z;
    }
    return weight > 0 ? rl::cast<float>(sum / weight) : rl::vec3{0, 0, 0};
}
// [/doc:prefilter]

rl::vec3 glossy_monte_carlo(const Environment& environment, rl::vec3 n, rl::vec3 v, float roughness,
                            rl::vec3 f0, int samples, std::uint32_t seed) {
    const Frame frame(rl::cast<double>(n));
    const rl::dvec3 to_eye = rl::cast<double>(v);
    const double alpha = ggx_alpha(roughness);
    const double n_dot_v = std::max(rl::dot(frame.n, to_eye), 1e-4);
    rl::dvec3 sum{0, 0, 0};
    for (int s = 0; s < samples; ++s) {
        const std::uint32_t bits = hash(seed ^ hash(static_cast<std::uint32_t>(s)));
        const rl::dvec3 h = frame.to_world(ggx_visible_normal(
            frame.to_local(to_eye), {unit_interval(bits), unit_interval(hash(bits))}, alpha));
        const double v_dot_h = rl::dot(to_eye, h);
        const rl::dvec3 l = h * (2 * v_dot_h) - to_eye;
        const double n_dot_l = rl::dot(frame.n, l);
        if (!(n_dot_l > 0 && v_dot_h > 0)) continue;  // below the surface (or not a number)
        const double weight =
            smith_masking(n_dot_v, n_dot_l, alpha) / smith_masking_one(n_dot_v, alpha);
        sum += schlick(v_dot_h, rl::cast<double>(f0)) * weight *
               rl::cast<double>(environment.sample(rl::cast<float>(l)));
    }
    return rl::cast<float>(sum / static_cast<double>(std::max(samples, 1)));
}

int glossy_face_size(double roughness, int largest) {
    const double alpha = std::max(ggx_alpha(roughness), 1e-6);
    const double wanted = std::min(4 * (0.5 * std::numbers::pi) / alpha, 1e6);
    const int size = static_cast<int>(std::bit_ceil(static_cast<unsigned>(wanted)));
    return std::clamp(size, 8, std::max(largest, 8));
}

GlossyMap::GlossyMap(const Environment& environment, GlossyOptions options)
    : environment_(&environment) {
    const auto check = [](int value, int low, int high, const char* what) {
        if (value < low || value > high)
            throw std::invalid_argument(std::string(what) + ": " + std::to_string(value) +
                                        " is outside " + std::to_string(low) + " to " +
                                        std::to_string(high));
    };
    check(options.levels, 2, kMaxGlossyLevels, "--glossy-levels");
    check(options.size, 8, kMaxGlossySize, "--glossy-size");
    check(options.samples, 1, kMaxGlossySamples, "--glossy-samples");
    const int sharpest = glossy_face_size(1.0 / (options.levels - 1), options.size);
    // A level with a quarter of the texels takes four times the samples:
    // every level costs about the same, and the rough ones, which gather a
    // bright sun from far off, are not left to a few lucky samples.
    const auto samples_for = [&](int size) {
        const long long scaled =
            static_cast<long long>(options.samples) * (sharpest / size) * (sharpest / size);
        return static_cast<int>(std::min<long long>(scaled, kMaxGlossySamples * 16LL));
    };
    long long work = 0;  // environment reads, all levels together
    for (int k = 1; k < options.levels; ++k) {
        const int size =
            glossy_face_size(static_cast<double>(k) / (options.levels - 1), options.size);
        work += 6LL * size * size * samples_for(size);
    }
    if (work > kMaxGlossyWork)
        throw std::invalid_argument(
            "--glossy-levels " + std::to_string(options.levels) + ", --glossy-size " +
            std::to_string(options.size) + " and --glossy-samples " +
            std::to_string(options.samples) + " ask for " + std::to_string(work) +
            " reads of the environment, over the " + std::to_string(kMaxGlossyWork) +
            " the blurred maps may take: lower one of them");
    for (int k = 1; k < options.levels; ++k) {
        const double roughness = static_cast<double>(k) / (options.levels - 1);
        const int size = glossy_face_size(roughness, options.size);
        const int samples = samples_for(size);
        const std::vector<LobeSample> lobe = ggx_lobe(environment, roughness, samples);
        blurred_.push_back(cube_map(
            [&](rl::dvec3 d) {
                return rl::cast<double>(prefiltered_radiance(environment, rl::normalize(d), lobe));
            },
            size, 1));
    }
}

rl::vec3 GlossyMap::sample(rl::vec3 r, float roughness, float mirror_level) const {
    const float x = (std::isfinite(roughness) ? std::clamp(roughness, 0.0f, 1.0f) : 0.0f) *
                    static_cast<float>(levels() - 1);
    const int k = std::min(static_cast<int>(x), levels() - 2);
    const float t = x - static_cast<float>(k);
    const auto at = [&](int level) {
        return level == 0
                   ? environment_->sample(r, mirror_level)
                   : blurred_[static_cast<std::size_t>(level - 1)].sample(r, MapFilter::seamless);
    };
    const rl::vec3 a = at(k);
    return t == 0 ? a : a * (1 - t) + at(k + 1) * t;
}

std::size_t GlossyMap::bytes() const {
    std::size_t sum = 0;
    for (const CubeMap& c : blurred_)
        sum += 6 * static_cast<std::size_t>(c.size()) * static_cast<std::size_t>(c.size()) *
               sizeof(rl::vec4);
    return sum;
}

namespace {

// "+x" -> "px", "-z" -> "nz": names a shell need not quote.
std::string file_face(Face face) {
    std::string text = name(face);
    text[0] = text[0] == '+' ? 'p' : 'n';
    return text;
}

}  // namespace

std::vector<MapFile> map_files(const Environment& environment, const GlossyMap* glossy) {
    std::vector<MapFile> files;
    if (const CubeMap* cube = environment.cube()) {
        for (int level = 0; level < cube->levels(); ++level)
            for (Face face : kFaces)
                files.push_back({"cube_" + file_face(face) + "_" + std::to_string(level) + ".hdr",
                                 &cube->face(face).level(level)});
    } else {
        const LatLongMap& latlong = *environment.latlong();
        for (int level = 0; level < latlong.map().levels(); ++level)
            files.push_back(
                {"latlong_" + std::to_string(level) + ".hdr", &latlong.map().level(level)});
    }
    if (glossy)
        for (int k = 1; k < glossy->levels(); ++k)
            for (Face face : kFaces)
                files.push_back({"glossy_" + std::to_string(k) + "_" + file_face(face) + ".hdr",
                                 &glossy->level(k).face(face).level(0)});
    return files;
}

}  // namespace environment
