#include "sampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace textures {

rl::vec4 to_vec4(rl::Rgba c) {
    return rl::vec4{float(c.r), float(c.g), float(c.b), float(c.a)} / 255.0f;
}

rl::Rgba to_rgba(rl::vec4 c) {
    // Rounded to nearest, halves up: what std::lround gives for these
    // non-negative values (exactly, in double), without its library call.
    auto byte = [](float x) {
        const float v = std::clamp(x, 0.0f, 1.0f) * 255.0f;
        if (!(v >= 0)) return std::uint8_t{0};  // NaN
        return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(v) + 0.5));
    };
    return {byte(c.x), byte(c.y), byte(c.z), byte(c.w)};
}

// [doc:downsample]
// decode(texel) gives its four values; encode(sums / total) the texel that
// stores their averages.
template <class Texel, class Decode, class Encode>
rl::Grid<Texel> average_down(const rl::Grid<Texel>& image, Decode&& decode, Encode&& encode) {
    const int w = std::max(1, image.width() / 2), h = std::max(1, image.height() / 2);
    const double sx = double(image.width()) / w,
                 sy = double(image.height()) / h;  // 2, or a bit more if odd
    rl::Grid<Texel> out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The output texel covers [x*sx, (x+1)*sx) x [y*sy, (y+1)*sy) of the input.
            std::array<double, 4> sum = {0, 0, 0, 0};
            double total = 0;
            for (int j = static_cast<int>(y * sy);
                 j < std::min(image.height(), static_cast<int>(std::ceil((y + 1) * sy))); ++j)
                for (int i = static_cast<int>(x * sx);
                     i < std::min(image.width(), static_cast<int>(std::ceil((x + 1) * sx))); ++i) {
                    const double wx =
                        std::min<double>(i + 1, (x + 1) * sx) - std::max<double>(i, x * sx);
                    const double wy =
                        std::min<double>(j + 1, (y + 1) * sy) - std::max<double>(j, y * sy);
                    const double weight = wx * wy;
                    const std::array<double, 4> v = decode(image.get(i, j));
                    for (std::size_t k = 0; k < 4; ++k) sum[k] += weight * v[k];
                    total += weight;
                }
            for (double& s : sum) s /= total;
            out.set(x, y, encode(sum));
        }
    return out;
}

template <>
rl::Image downsample(const rl::Image& image, const TexelEncoding* encoding) {
    // Alpha is averaged as bytes; the colour as the values the bytes stand
    // for (through the encoding, then encoded again), or as bytes without one.
    const auto value = [&](std::uint8_t c) {
        return encoding ? double(encoding->value[c]) : double(c);
    };
    const auto byte = [&](double v) {
        return encoding ? encoding->to_byte(static_cast<float>(v))
                        : static_cast<std::uint8_t>(std::lround(v));
    };
    return average_down(
        image,
        [&](rl::Rgba c) {
            return std::array<double, 4>{value(c.r), value(c.g), value(c.b), double(c.a)};
        },
        [&](const std::array<double, 4>& m) {
            return rl::Rgba{byte(m[0]), byte(m[1]), byte(m[2]),
                            static_cast<std::uint8_t>(std::lround(m[3]))};
        });
}

template <>
rl::Grid<rl::vec4> downsample(const rl::Grid<rl::vec4>& image, const TexelEncoding* encoding) {
    if (encoding) throw std::invalid_argument("float texels are values already: no encoding");
    return average_down(
        image,
        [](const rl::vec4& c) {
            return std::array<double, 4>{c.x, c.y, c.z, c.w};
        },
        [](const std::array<double, 4>& m) {
            return rl::vec4{static_cast<float>(m[0]), static_cast<float>(m[1]),
                            static_cast<float>(m[2]), static_cast<float>(m[3])};
        });
}
// [/doc:downsample]

template <TexelType Texel>
BasicMipChain<Texel>::BasicMipChain(Level image, const TexelEncoding* encoding)
    : base_(std::make_shared<const Level>(std::move(image))),
      encoding_(encoding),
      smaller_(std::make_shared<Smaller>()) {
    if (std::same_as<Texel, rl::vec4> && encoding)
        throw std::invalid_argument("float texels are values already: no encoding");
}

template <TexelType Texel>
const std::vector<typename BasicMipChain<Texel>::Level>& BasicMipChain<Texel>::smaller() const {
    std::call_once(smaller_->built, [this] {
        std::vector<Level>& levels = smaller_->levels;
        const auto last = [&]() -> const Level& { return levels.empty() ? *base_ : levels.back(); };
        while (last().width() > 1 || last().height() > 1) {
            Level next = downsample(last(), encoding_);  // before push_back moves the levels
            levels.push_back(std::move(next));
        }
    });
    return smaller_->levels;
}

template class BasicMipChain<rl::Rgba>;
template class BasicMipChain<rl::vec4>;

// [doc:wrap]
int wrap_texel(int i, int size, Wrap wrap) {
    if (i >= 0 && i < size) return i;  // inside: every mode agrees (and no division)
    switch (wrap) {
        case Wrap::repeat:
            return ((i % size) + size) % size;
        case Wrap::mirror: {
            const int period = ((i % (2 * size)) + 2 * size) % (2 * size);  // 0 .. 2*size-1
            return period < size ? period : 2 * size - 1 - period;
        }
        case Wrap::clamp:
            return std::clamp(i, 0, size - 1);
        case Wrap::border:
            return i < 0 || i >= size ? -1 : i;
    }
    return 0;
}
// [/doc:wrap]

namespace {

// wrap_texel with its common case, an index inside, inlined (it runs for
// every texel of every lookup).
inline int wrapped(int i, int size, Wrap wrap) {
    return i >= 0 && i < size ? i : wrap_texel(i, size, wrap);
}

// The texel at wrapped indices (x, y); -1 in either: the border colour.
template <TexelType Texel>
[[gnu::always_inline]] inline rl::vec4 fetch(const rl::Grid<Texel>& level, int x, int y,
                                             const SamplerState& state) {
    if (x < 0 || y < 0) return state.border;
    if constexpr (std::same_as<Texel, rl::vec4>) {
        return level.get(x, y);  // values already
    } else {
        const rl::Rgba c = level.get(x, y);
        if (!state.encoding) return to_vec4(c);
        const std::array<float, 256>& value = state.encoding->value;
        return {value[c.r], value[c.g], value[c.b], float(c.a) / 255.0f};
    }
}

template <TexelType Texel>
rl::vec4 texel(const rl::Grid<Texel>& level, int i, int j, const SamplerState& state) {
    return fetch(level, wrapped(i, level.width(), state.wrap),
                 wrapped(j, level.height(), state.wrap), state);
}

// Texel coordinates are computed in double after reducing u to one period:
// with `repeat`, u = 10000.3 and u = 0.3 must give the same texel, and the
// float u itself already holds only 0.001 of precision at 10^4. With clamp
// and border there is no period: the coordinate is clamped in floating point
// to two texels beyond the edges (every texel there clamps, or is border,
// alike), so that converting it to int can never overflow (u * width passed
// 2^31 at u = 10^7 and drew black where the edge texel belonged).
double to_texels(float u, int size, Wrap wrap) {
    double t = static_cast<double>(u);
    if (wrap == Wrap::repeat) t -= std::floor(t);
    if (wrap == Wrap::mirror) t -= 2.0 * std::floor(t / 2.0);
    if (wrap == Wrap::clamp || wrap == Wrap::border)
        return std::clamp(t * size, -2.0, static_cast<double>(size) + 2.0);
    return t * size;
}

}  // namespace

// [doc:sample-level]
template <TexelType Texel>
rl::vec4 sample_level(const rl::Grid<Texel>& level, rl::vec2 uv, bool bilinear,
                      const SamplerState& state) {
    const double s = to_texels(uv.x, level.width(), state.wrap),
                 t = to_texels(uv.y, level.height(), state.wrap);
    if (!bilinear)  // (s, t >= 0 unless clamped or bordered: then truncating is flooring)
        return texel(level, static_cast<int>(s >= 0 ? s : std::floor(s)),
                     static_cast<int>(t >= 0 ? t : std::floor(t)), state);
    // The four texel centres around (s, t): centres sit at half-integers.
    const double x = s - 0.5, y = t - 0.5;
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const float fx = static_cast<float>(x - i), fy = static_cast<float>(y - j);
    const int x0 = wrapped(i, level.width(), state.wrap),
              x1 = wrapped(i + 1, level.width(), state.wrap);
    const int y0 = wrapped(j, level.height(), state.wrap),
              y1 = wrapped(j + 1, level.height(), state.wrap);
    const rl::vec4 bottom =
        fetch(level, x0, y0, state) * (1 - fx) + fetch(level, x1, y0, state) * fx;
    const rl::vec4 top = fetch(level, x0, y1, state) * (1 - fx) + fetch(level, x1, y1, state) * fx;
    return bottom * (1 - fy) + top * fy;
}
// [/doc:sample-level]

// [doc:lod]
float level_of_detail(const UvDerivatives& d, int width, int height) {
    const rl::vec2 size{float(width), float(height)};
    const float along_x = rl::length(d.dx * size), along_y = rl::length(d.dy * size);  // in texels
    return std::log2(std::max({along_x, along_y, 1e-20f}));
}
// [/doc:lod]

template <TexelType Texel>
rl::vec4 sample(const BasicMipChain<Texel>& texture, rl::vec2 uv, const UvDerivatives& derivatives,
                const SamplerState& state) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return state.border;
    switch (state.filter) {
        case Filter::nearest:
            return sample_level(texture.level(0), uv, false, state);
        case Filter::bilinear:
            return sample_level(texture.level(0), uv, true, state);
        case Filter::trilinear:
            break;
    }
    // [doc:trilinear]
    const rl::Grid<Texel>& base = texture.level(0);
    float lod = level_of_detail(derivatives, base.width(), base.height());
    if (!std::isfinite(lod)) lod = 0;
    lod = std::clamp(lod, 0.0f, static_cast<float>(texture.levels() - 1));
    const int lower = static_cast<int>(std::floor(lod));
    const int upper = std::min(lower + 1, texture.levels() - 1);
    const float blend = lod - static_cast<float>(lower);
    const rl::vec4 a = sample_level(texture.level(lower), uv, true, state);
    if (blend == 0 || upper == lower) return a;
    return a * (1 - blend) + sample_level(texture.level(upper), uv, true, state) * blend;
    // [/doc:trilinear]
}

template rl::vec4 sample(const MipChain&, rl::vec2, const UvDerivatives&, const SamplerState&);
template rl::vec4 sample(const HdrMipChain&, rl::vec2, const UvDerivatives&, const SamplerState&);
template rl::vec4 sample_level(const rl::Image&, rl::vec2, bool, const SamplerState&);
template rl::vec4 sample_level(const rl::Grid<rl::vec4>&, rl::vec2, bool, const SamplerState&);

}  // namespace textures
