#include "renderer.hpp"

#include "orbit.hpp"
#include "rasterlab/checkpoint.hpp"
#include "rasterlab/workers.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace fast {

namespace {

// Faces a piece of the set-up holds: enough that a piece outweighs its
// scheduling, few enough that two threads share a model of 10 000 faces.
constexpr std::size_t kPieceFaces = 2048;

using Clock = std::chrono::steady_clock;
double milliseconds_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// What makes two corners one vertex: the same position and uv indices and
// the same normal and tangent (compared as bits: the vertex function reads
// nothing else).
struct CornerKey {
    int position, uv;
    std::uint32_t normal[3], tangent[4];
    friend bool operator==(const CornerKey&, const CornerKey&) = default;
};
struct CornerHash {
    std::size_t operator()(const CornerKey& k) const {
        std::size_t h = static_cast<std::size_t>(k.position) * 0x9e3779b97f4a7c15ull ^
                        static_cast<std::size_t>(k.uv + 1);
        for (std::uint32_t v : k.normal) h = (h ^ v) * 0x100000001b3ull;
        for (std::uint32_t v : k.tangent) h = (h ^ v) * 0x100000001b3ull;
        return h;
    }
};

std::unique_ptr<PackedTexture> packed(const std::optional<textures::MipChain>& chain,
                                      bool all_levels) {
    return chain ? std::make_unique<PackedTexture>(*chain, all_levels) : nullptr;
}

[[noreturn]] void throw_binning_cap(std::size_t entries, std::size_t cap, int tile) {
    char message[256];
    std::snprintf(message, sizeof message,
                  "binning this frame needs %.3g tile entries (%.2f GiB), more than the cap of "
                  "%.3g (%.2f GiB): raise --tile-size (now %d), or lower --width/--height",
                  static_cast<double>(entries), static_cast<double>(entries) * 4 / (1u << 30),
                  static_cast<double>(cap), static_cast<double>(cap) * 4 / (1u << 30), tile);
    throw std::invalid_argument(message);
}

}  // namespace

FastModel fast_model(const normal_mapping::MappedModel& model, const FastOptions& options) {
    FastModel out;
    out.source = &model;
    const rl::Mesh& mesh = model.lit.model.mesh;
    std::unordered_map<CornerKey, std::uint32_t, CornerHash> seen;
    out.indices.resize(mesh.faces.size() * 3);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (std::size_t c = 0; c < 3; ++c) {
            const std::size_t corner = 3 * f + c;
            CornerKey key{mesh.faces[f].corners[c].position, mesh.faces[f].corners[c].uv, {}, {}};
            std::memcpy(key.normal, &model.lit.normals[corner], sizeof key.normal);
            std::memcpy(key.tangent, &model.tangents[corner], sizeof key.tangent);
            const auto [at, added] =
                seen.try_emplace(key, static_cast<std::uint32_t>(out.representative.size()));
            if (added) out.representative.push_back(static_cast<std::uint32_t>(corner));
            out.indices[corner] = at->second;
        }
    if (options.depth_only) return out;  // positions only: no texture is read
    const bool all_levels = options.render.filter == textures::Filter::trilinear;
    // The diffuse texture holds sRGB colours unless the output is naive (lesson 06).
    out.albedo = std::make_unique<PackedTexture>(
        model.lit.model.texture, all_levels,
        options.render.output == shading::Output::srgb ? &shading::srgb_texels() : nullptr,
        options.albedo_in_one_word);
    out.tangent_map = packed(model.maps.tangent_normals, all_levels);
    out.object_map = packed(model.maps.object_normals, all_levels);
    out.specular_map = packed(model.maps.specular, all_levels);
    // The specular map in the normal maps' alpha bytes where their levels
    // match: the normal's lookup then reads the specular value too, and the
    // shader gathers no texel of the specular map (docs/12_fast.md,
    // "Textures laid out for the gathers"). Kept on its own as well, for
    // frames without a normal map.
    if (options.specular_in_normal_alpha && model.maps.specular)
        for (PackedTexture* normals : {out.tangent_map.get(), out.object_map.get()})
            if (normals) normals->take_alpha_from(*model.maps.specular);
    return out;
}

struct Renderer::Impl {
    FastOptions options;
    int width, height;
    zbuffer::DepthState map_bias;  // a shadow map's pass: lesson 08's constant and slope bias
    rl::Workers workers;
    std::vector<FastModel> models;
    // Per model, set once: lesson 06's uniforms (only the MVP and the eye
    // change from frame to frame) and the surface; empty for a model whose
    // matrix flattens it.
    std::vector<std::optional<shading::Placed>> placed;
    std::vector<Material> materials;
    const shadows::ShadowMap* shadow_map = nullptr;  // set_shadow_map()'s, for every material
    shadows::ShadowLookup shadow_lookup;
    std::vector<std::vector<pipeline::ClipVertex<Varyings>>> clip;  // per model, per vertex
    std::vector<char> drawn;                                        // per model, this frame
    std::vector<pipeline::MeshView> views;  // per model: lesson 05's view, its corner order
    // The faces in pieces of at most kPieceFaces, each set up by one thread
    // into its own triangles; `triangles` reads them as one array, in order.
    // The pieces depend on the models only, never on the thread count.
    struct Piece {
        std::size_t model, first_face, faces;
        std::vector<FastTriangle> triangles;
        pipeline::PipelineCounts counts;  // culled, clipped, outside, refused
        double visited = 0;               // pixels in the triangles' boxes (the overdraw cap)
    };
    std::vector<Piece> pieces;
    TriangleChunks triangles;
    // Binning, in parts of the triangles (one a thread): each part's entries
    // per tile, then where it writes them (tiles x parts, reused).
    std::vector<std::size_t> part_entries, part_bins;
    int tiles_x, tiles_y;
    // The bins, as one array sorted by tile (a counting sort): tile i's
    // triangles are binned[bin_start[i] .. bin_start[i + 1]), in drawing order.
    std::size_t tiles = 0;
    std::vector<std::size_t> bin_start;  // 64-bit: the entries can pass 2^32
    std::vector<std::uint32_t> binned;
    std::vector<TileCounts> tile_counts;                // per tile
    std::vector<std::unique_ptr<TileBuffers>> buffers;  // per worker thread

    Impl(const std::vector<normal_mapping::MappedModel>& sources, int w, int h,
         const FastOptions& o)
        : options(o), width(w), height(h), workers(o.threads) {
        map_bias.constant_bias = o.constant_bias, map_bias.slope_bias = o.slope_bias;
        if (o.tile_size < kBlock || o.tile_size % kBlock != 0 || o.tile_size > 1024)
            throw std::invalid_argument(
                "--tile-size: must be a multiple of 8 from 8 to 1024, not " +
                std::to_string(o.tile_size));
        const normal_mapping::RenderOptions& r = o.render;
        if (r.pipeline.raster != triangles::RasterMethod::edge)
            throw std::invalid_argument(
                "the fast path rasterizes with lesson 02's edge functions only");
        for (const normal_mapping::MappedModel& m : sources) {
            try {
                models.push_back(fast_model(m, o));
            } catch (const std::bad_alloc&) {
                throw std::runtime_error(m.lit.model.mesh.source.string() +
                                         ": out of memory packing this model's textures for the "
                                         "fast path (their size is the cause, not the image's)");
            }
            placed.push_back(std::nullopt);
            views.push_back(pipeline::MeshView(m.lit.model.mesh, m.lit.model.transform));
            clip.emplace_back(o.vertex_cache ? models.back().representative.size()
                                             : models.back().indices.size());
            if (o.depth_only) {  // nothing is shaded: no surface, no material
                materials.emplace_back();
                continue;
            }
            if (const std::optional<rl::mat3> normals =
                    shading::normal_matrix(m.lit.model.transform)) {
                // Member by member: a trailing {} by position zeroed `colour`.
                shading::Uniforms u;
                u.model_matrix = m.lit.model.transform;
                u.normal_matrix = *normals;
                u.lighting = r.lighting;
                u.texture = &m.lit.model.texture;
                placed.back() = shading::Placed{
                    u, shading::Surface(m.lit.model.mesh, m.lit.normals, m.lit.model.transform)};
            }
            materials.push_back(material_for(models.back(), placed.back()));
        }
        drawn.resize(models.size());
        for (std::size_t i = 0; i < models.size(); ++i) {
            const std::size_t faces = models[i].indices.size() / 3;
            for (std::size_t first = 0; first < faces; first += kPieceFaces) {
                Piece& piece = pieces.emplace_back();
                piece.model = i, piece.first_face = first;
                piece.faces = std::min(kPieceFaces, faces - first);
                piece.triangles.reserve(piece.faces + piece.faces / 4 + 16);
            }
        }
        triangles.data.resize(pieces.size());
        triangles.start.resize(pieces.size() + 1);
        tiles_x = (width + o.tile_size - 1) / o.tile_size;
        tiles_y = (height + o.tile_size - 1) / o.tile_size;
        tiles = static_cast<std::size_t>(tiles_x) * static_cast<std::size_t>(tiles_y);
        bin_start.resize(tiles + 1);
        tile_counts.resize(tiles);
        for (int i = 0; i < workers.threads(); ++i)
            buffers.push_back(std::make_unique<TileBuffers>(o.tile_size));
    }

    // The frame's four steps (Renderer::render times each).
    void run_vertex_stage(const pipeline::Camera& camera, FrameCounts& counts);
    void set_up_triangles(FrameCounts& counts);
    void set_up_piece(Piece& piece, const pipeline::ClipPlanes& planes);
    void keep_triangle(Piece& piece, const Setup& t);
    void join_pieces(pipeline::PipelineCounts& counts);
    void bin_triangles();
    void draw_tiles(rl::Image& frame);
    // render_depth()'s own first and last steps.
    void run_depth_vertex_stage(const rl::mat4& view_projection, FrameCounts& counts);
    void draw_depth_tiles(rl::FloatImage& depth);
    template <class Vertices, class Tiles>
    FrameCounts timed_frame(StageTimes& times, Vertices&& vertex_step, Tiles&& tile_step);
    // body(v) for each of model m's vertices of the vertex stage, on the threads.
    template <class Body>
    void for_each_vertex(const FastModel& m, FrameCounts& counts, Body&& body);
    // body(tile index, its work, this thread's buffers) for each tile, on the threads.
    template <class Body>
    void for_each_tile(Body&& body);

    Material material_for(const FastModel& m, const std::optional<shading::Placed>& p) const {
        const normal_mapping::RenderOptions& r = options.render;
        Material out;
        const shading::Lighting<float>& lighting = r.lighting;
        if (lighting.lights.size() > static_cast<std::size_t>(kMaxLights))
            throw std::invalid_argument("the fast path takes at most 8 lights");
        out.lights = static_cast<int>(lighting.lights.size());
        for (int i = 0; i < out.lights; ++i)
            for (int c = 0; c < 3; ++c) {
                out.light_direction[i][c] = lighting.lights[static_cast<std::size_t>(i)]
                                                .direction[static_cast<std::size_t>(c)];
                out.light_colour[i][c] = lighting.lights[static_cast<std::size_t>(i)]
                                             .colour[static_cast<std::size_t>(c)];
            }
        for (std::size_t c = 0; c < 3; ++c) {
            out.ambient[c] = lighting.ambient[c];
            out.specular_colour[c] = lighting.specular[c];
            out.eye[c] = 0;
        }
        out.shininess = lighting.shininess;
        out.blinn = r.specular == shading::Specular::blinn_phong;
        if (p)
            for (std::size_t i = 0; i < 3; ++i)
                for (std::size_t j = 0; j < 3; ++j)
                    out.normal_matrix[3 * i + j] = p->uniforms.normal_matrix[i][j];
        out.filter = r.filter;
        out.srgb = r.output == shading::Output::srgb;
        out.srgb_one_gather = options.techniques.srgb_one_gather;
        out.albedo = m.albedo.get();
        const shading::Uniforms defaults{};
        for (std::size_t c = 0; c < 3; ++c) out.colour[c] = defaults.colour[c];
        if (r.normal_map == normal_mapping::NormalMap::tangent && m.tangent_map) {
            out.normal_source = NormalSource::tangent_map;
            out.normal_map = m.tangent_map.get();
        } else if (r.normal_map == normal_mapping::NormalMap::object && m.object_map) {
            out.normal_source = NormalSource::object_map;
            out.normal_map = m.object_map.get();
        }
        out.specular_map = m.specular_map.get();
        out.specular_in_normal_alpha =
            out.specular_map && out.normal_map && out.normal_map->alpha_holds_other;
        out.shadow_map = shadow_map;
        out.shadow_lookup = shadow_lookup;
        return out;
    }
};

Renderer::Renderer(const std::vector<normal_mapping::MappedModel>& models, int width, int height,
                   const FastOptions& options)
    : impl_(std::make_unique<Impl>(models, width, height, options)), frame_(width, height) {}

Renderer::~Renderer() = default;

void Renderer::set_lighting(const shading::Lighting<float>& lighting) {
    Impl& s = *impl_;
    if (lighting.lights.size() > static_cast<std::size_t>(kMaxLights))
        throw std::invalid_argument("the fast path takes at most 8 lights");
    s.options.render.lighting = lighting;
    if (s.options.depth_only) return;  // it shades nothing
    for (std::size_t m = 0; m < s.models.size(); ++m) {
        if (s.placed[m]) s.placed[m]->uniforms.lighting = lighting;
        s.materials[m] = s.material_for(s.models[m], s.placed[m]);
    }
}

void Renderer::set_shadow_map(const shadows::ShadowMap* map, const shadows::ShadowLookup& lookup) {
    Impl& s = *impl_;
    if (map && map->light.type == shadows::LightType::spot)
        throw std::invalid_argument(
            "the fast path's shadows take a directional light's map, not a spot light's");
    s.shadow_map = map, s.shadow_lookup = lookup;
    for (Material& m : s.materials) m.shadow_map = map, m.shadow_lookup = lookup;
}

int Renderer::threads() const {
    return impl_->workers.threads();
}

// 1. The vertex stage: lesson 07's vertex function, once per distinct vertex.
void Renderer::Impl::run_vertex_stage(const pipeline::Camera& camera, FrameCounts& counts) {
    Impl& s = *this;
    const normal_mapping::RenderOptions& r = s.options.render;
    const float aspect = static_cast<float>(s.width) / static_cast<float>(s.height);
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    for (std::size_t i = 0; i < s.models.size(); ++i) {
        s.drawn[i] = false;
        if (!s.placed[i]) continue;
        shading::Placed& p = *s.placed[i];
        const pipeline::TexturedModel& model = s.models[i].source->lit.model;
        p.uniforms.model_view_projection = view_projection * model.transform;
        p.uniforms.eye = camera.eye;
        for (std::size_t c = 0; c < 3; ++c) s.materials[i].eye[c] = camera.eye[c];
        if (r.cull_objects &&
            pipeline::outside_frustum(model.box, p.uniforms.model_view_projection)) {
            ++counts.pipeline.objects_culled;
            continue;
        }
        s.drawn[i] = true;
        const normal_mapping::NormalMappedShader shader =
            normal_mapping::shader_for(*s.models[i].source, p, r);
        const FastModel& m = s.models[i];
        std::vector<pipeline::ClipVertex<Varyings>>& out = s.clip[i];
        s.for_each_vertex(m, counts, [&](std::size_t v) {
            if (s.options.vertex_cache) {
                const int face = static_cast<int>(m.representative[v] / 3);
                const int corner = static_cast<int>(m.representative[v] % 3);
                // Mesh corner `corner` is the surface's corner k.
                const int k = p.surface.view.mesh_corner(corner);
                out[v] = shader.vertex(p.surface.corner(face, k));
            } else {  // every corner of every face, in the surface's order
                out[v] = shader.vertex(
                    p.surface.corner(static_cast<int>(v / 3), static_cast<int>(v % 3)));
            }
        });
    }
}

template <class Body>
void Renderer::Impl::for_each_vertex(const FastModel& m, FrameCounts& counts, Body&& body) {
    // With the vertex cache, each distinct vertex; without, every corner.
    const std::size_t count = options.vertex_cache ? m.representative.size() : m.indices.size();
    counts.vertices += count;
    counts.pipeline.faces += m.indices.size() / 3;
    const auto chunk = [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v) body(v);
    };
    if (options.parallel)
        workers.for_chunks(count, 1024, chunk);
    else
        chunk({0, count});
}

// 1, for a shadow map: the positions alone, as lesson 08's depth program
// computes them (no varyings: nothing is shaded).
void Renderer::Impl::run_depth_vertex_stage(const rl::mat4& view_projection, FrameCounts& counts) {
    for (std::size_t i = 0; i < models.size(); ++i) {
        drawn[i] = true;  // lesson 08's pass culls no object
        const FastModel& m = models[i];
        const pipeline::TexturedModel& model = m.source->lit.model;
        const rl::mat4 model_view_projection = view_projection * model.transform;
        std::vector<pipeline::ClipVertex<Varyings>>& out = clip[i];
        const pipeline::MeshView& view = views[i];
        for_each_vertex(m, counts, [&](std::size_t v) {
            // With the vertex cache, mesh corner c (a vertex's position does
            // not depend on the order the corners are handed over in);
            // without it, corner v in the surface's order, as lesson 05's
            // MeshView hands it over.
            std::size_t c = v;
            if (options.vertex_cache)
                c = m.representative[v];
            else
                c = c / 3 * 3 + static_cast<std::size_t>(view.mesh_corner(static_cast<int>(c % 3)));
            const pipeline::MeshCorner corner{&model.mesh, static_cast<int>(c / 3),
                                              static_cast<int>(c % 3)};
            out[v] = {pipeline::clip_position(model_view_projection, corner.position()), {}};
        });
    }
}

// 2. Cull, clip and set up every face, in lesson 07's order: the pieces
// in parallel, each into its own triangles.
void Renderer::Impl::set_up_triangles(FrameCounts& counts) {
    const pipeline::ClipPlanes planes =
        pipeline::clip_planes(options.render.pipeline.clip, width, height);
    if (options.parallel)
        workers.for_chunks(pieces.size(), 1, [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t c = range.begin(); c != range.end(); ++c)
                set_up_piece(pieces[c], planes);
        });
    else
        for (Piece& piece : pieces) set_up_piece(piece, planes);
    join_pieces(counts.pipeline);
}

// One piece's faces through lesson 05's stages 2-4 (cull, clip, divide and
// viewport, set-up), each triangle that comes out kept as a fast triangle.
void Renderer::Impl::set_up_piece(Piece& piece, const pipeline::ClipPlanes& planes) {
    piece.triangles.clear();
    piece.counts = {}, piece.visited = 0;
    const std::size_t i = piece.model;
    if (!drawn[i]) return;
    const FastModel& m = models[i];
    const pipeline::MeshView& view = views[i];
    const std::vector<pipeline::ClipVertex<Varyings>>& vertices = clip[i];
    for (std::size_t f = piece.first_face; f < piece.first_face + piece.faces; ++f) {
        // The corners of step 1: with the vertex cache, three indices into
        // the distinct vertices, swapped as the surface swaps them when
        // mirrored; without it, already in the surface's order.
        // (Read where they are: a face culled costs no copy of its corners.)
        std::size_t corner[3] = {3 * f, 3 * f + 1, 3 * f + 2};
        if (options.vertex_cache)
            for (int k = 0; k < 3; ++k) corner[k] = m.indices[3 * f + view.mesh_corner(k)];
        pipeline::assemble_face(vertices[corner[0]], vertices[corner[1]], vertices[corner[2]],
                                static_cast<int>(f), planes, width, height, options.render.pipeline,
                                piece.counts, [&](const Setup& t) { keep_triangle(piece, t); });
    }
}

// A set-up triangle as the tiles take it (snapped, its box and edges), or
// counted refused; one that covers no pixel centre is dropped.
void Renderer::Impl::keep_triangle(Piece& piece, const Setup& t) {
    // A shadow map's pass counts its work as lesson 08's does (by lesson
    // 05's boxes, before the fixed-point snap).
    if (options.depth_only)
        piece.visited += static_cast<double>(
            pipeline::box_samples(t.screen(), triangles::PixelRect{0, 0, width, height}));
    FastTriangle& fast = piece.triangles.emplace_back();
    if (!fast_triangle(t, static_cast<std::uint32_t>(piece.model), width, height, fast)) {
        piece.triangles.pop_back();
        ++piece.counts.refused;
        return;
    }
    if (fast.empty()) {
        piece.triangles.pop_back();
        return;
    }
    if (options.depth_only) {
        // [doc:depth-bias]
        // Lesson 08's bias, once per triangle, and the nearest depth it
        // can then give (for the hierarchical depth test).
        fast.depth_bias = pipeline::depth_bias(t, map_bias);
        if (fast.depth_bias != 0)
            fast.z_nearest = std::clamp(fast.z_min + fast.depth_bias, 0.0f, 1.0f);
        // [/doc:depth-bias]
    } else {
        piece.visited += static_cast<double>(fast.x1 - fast.x0 + 1) * (fast.y1 - fast.y0 + 1);
    }
}

// The pieces, in order, as one array of triangles; their counts added up and
// the overdraw cap applied over all of them (a shadow map's pass: each model
// on its own, as lesson 08's does).
void Renderer::Impl::join_pieces(pipeline::PipelineCounts& counts) {
    const pipeline::PipelineOptions& pipeline = options.render.pipeline;
    // (A picture's cap of 0 or less is no cap; a map's is lesson 08's, 0 included.)
    const double most_visited = pipeline.max_overdraw > 0 || options.depth_only
                                    ? pipeline.max_overdraw * width * height
                                    : HUGE_VAL;
    double visited = 0;
    std::size_t total = 0;
    for (std::size_t c = 0; c < pieces.size(); ++c) {
        const Piece& piece = pieces[c];
        counts += piece.counts;
        if (options.depth_only && c > 0 && piece.model != pieces[c - 1].model) {
            if (visited > most_visited) pipeline::throw_overdraw(most_visited);
            visited = 0;
        }
        visited += piece.visited;
        triangles.data[c] = piece.triangles.data();
        triangles.start[c] = static_cast<std::uint32_t>(total);
        total += piece.triangles.size();
        if (total >= std::numeric_limits<std::uint32_t>::max())
            throw std::runtime_error("more than 2^32 - 2 triangles in one frame");
    }
    triangles.start.back() = static_cast<std::uint32_t>(total);
    if (visited > most_visited) pipeline::throw_overdraw(most_visited);
    counts.drawn = total;
}

// 3. Binning: each triangle into the tiles its box touches, in drawing
// order. In parts of the triangles, one a thread: each part counts its
// entries per tile, the counts give each part where it writes in each
// tile's bin (after the parts before it), and each part writes its own.
void Renderer::Impl::bin_triangles() {
    Impl& s = *this;
    const std::size_t total = s.triangles.size();
    const int tile = s.options.tile_size;
    const auto each_tile_of = [&](const FastTriangle& f, auto&& visit) {
        for (int ty = f.y0 / tile; ty <= f.y1 / tile; ++ty)
            for (int tx = f.x0 / tile; tx <= f.x1 / tile; ++tx)
                visit(static_cast<std::size_t>(ty * s.tiles_x + tx));
    };
    // As many parts as threads, unless their counts would pass 2^24 (tiles
    // of 8 at 16384²): then one part.
    std::size_t parts = s.options.parallel ? static_cast<std::size_t>(s.workers.threads()) : 1;
    if (parts * s.tiles > (std::size_t{1} << 24)) parts = 1;
    parts = std::max<std::size_t>(1, std::min<std::size_t>(parts, total));
    const auto in_parts = [&](auto&& body) {  // body(part, first triangle, end)
        const auto run = [&](std::size_t p) {
            body(p, static_cast<std::uint32_t>(total * p / parts),
                 static_cast<std::uint32_t>(total * (p + 1) / parts));
        };
        if (parts == 1)
            run(0);
        else
            s.workers.for_chunks(parts, 1, [&](const tbb::blocked_range<std::size_t>& range) {
                for (std::size_t p = range.begin(); p != range.end(); ++p) run(p);
            });
    };
    // Counted first, so that a frame over the cap costs nothing more.
    s.part_entries.assign(parts, 0);
    in_parts([&](std::size_t p, std::uint32_t first, std::uint32_t end) {
        std::size_t piece = 0, entries = 0;
        for (std::uint32_t t = first; t < end; ++t) {
            const FastTriangle& f = s.triangles.at(t, piece);
            entries += static_cast<std::size_t>(f.x1 / tile - f.x0 / tile + 1) *
                       static_cast<std::size_t>(f.y1 / tile - f.y0 / tile + 1);
        }
        s.part_entries[p] = entries;
    });
    std::size_t entries = 0;
    for (std::size_t e : s.part_entries) entries += e;
    if (entries > s.options.max_binned_entries)
        throw_binning_cap(entries, s.options.max_binned_entries, tile);
    // [doc:binning]
    // part_bins[p * tiles + i]: part p's entries in tile i, then where it writes them.
    s.part_bins.assign(parts * s.tiles, 0);
    in_parts([&](std::size_t p, std::uint32_t first, std::uint32_t end) {
        std::size_t* mine = s.part_bins.data() + p * s.tiles;
        std::size_t piece = 0;
        for (std::uint32_t t = first; t < end; ++t)
            each_tile_of(s.triangles.at(t, piece), [&](std::size_t i) { ++mine[i]; });
    });
    std::size_t next = 0;
    for (std::size_t i = 0; i < s.tiles; ++i) {
        s.bin_start[i] = next;
        for (std::size_t p = 0; p < parts; ++p) {
            const std::size_t n = s.part_bins[p * s.tiles + i];
            s.part_bins[p * s.tiles + i] = next;
            next += n;
        }
    }
    s.bin_start[s.tiles] = next;
    // Grown by half again when a frame needs more, so that an orbit's
    // frames after the first rarely need to grow it at all.
    if (entries > s.binned.size())
        s.binned.resize(std::min(entries * 3 / 2, std::max(entries, s.options.max_binned_entries)));
    in_parts([&](std::size_t p, std::uint32_t first, std::uint32_t end) {
        std::size_t* write = s.part_bins.data() + p * s.tiles;
        std::size_t piece = 0;
        for (std::uint32_t t = first; t < end; ++t)
            each_tile_of(s.triangles.at(t, piece),
                         [&](std::size_t i) { s.binned[write[i]++] = t; });
    });
    // [/doc:binning]
}

// 4. The tiles, in parallel: each one rasterized, shaded and copied into the frame by one
// thread.
void Renderer::Impl::draw_tiles(rl::Image& frame) {
    for_each_tile([&](std::size_t i, const TileWork& work, TileBuffers& own) {
        render_tile(work, own, frame, tile_counts[i]);
    });
}

template <class Body>
void Renderer::Impl::for_each_tile(Body&& body) {
    const int tile = options.tile_size;
    const auto draw_tile = [&](std::size_t i, TileBuffers& own) {
        const int tx = static_cast<int>(i) % tiles_x, ty = static_cast<int>(i) / tiles_x;
        const TileWork work{tx * tile,
                            ty * tile,
                            std::min(tile, width - tx * tile),
                            std::min(tile, height - ty * tile),
                            &triangles,
                            binned.data() + bin_start[i],
                            bin_start[i + 1] - bin_start[i],
                            materials.data(),
                            options.techniques};
        tile_counts[i] = {};
        rl::checkpoint();  // a host's Ctrl-C, between tiles
        body(i, work, own);
    };
    if (options.parallel)
        workers.for_chunks(tiles, 1, [&](const tbb::blocked_range<std::size_t>& range) {
            TileBuffers& own = *buffers[static_cast<std::size_t>(rl::Workers::this_thread())];
            for (std::size_t i = range.begin(); i != range.end(); ++i) draw_tile(i, own);
        });
    else
        for (std::size_t i = 0; i < tiles; ++i) draw_tile(i, *buffers[0]);
}

// 4, for a shadow map: each tile's visibility pass alone, its depth copied
// into the map (the tile buffers hold 8x8 blocks: one block's row at a time).
void Renderer::Impl::draw_depth_tiles(rl::FloatImage& depth) {
    for_each_tile([&](std::size_t i, TileWork work, TileBuffers& own) {
        work.techniques.shade_once = true;  // so that the pass shades nothing
        rasterize_tile(work, own, tile_counts[i]);
        const int blocks_per_row = own.size / kBlock;
        for (int y = 0; y < work.height; ++y) {
            float* row = &depth.at(work.x0, work.y0 + y);
            const float* block_row = own.depth.get() +
                                     static_cast<std::size_t>((y / kBlock) * blocks_per_row) * 64 +
                                     static_cast<std::size_t>((y % kBlock) * kBlock);
            for (int x = 0; x < work.width; x += kBlock)
                std::memcpy(row + x, block_row + (x / kBlock) * 64,
                            static_cast<std::size_t>(std::min(kBlock, work.width - x)) * 4);
        }
    });
}

// The frame's four steps, each timed: `vertex_step(counts)` runs the first,
// `tile_step()` the last.
template <class Vertices, class Tiles>
FrameCounts Renderer::Impl::timed_frame(StageTimes& times, Vertices&& vertex_step,
                                        Tiles&& tile_step) {
    FrameCounts counts;
    auto start = Clock::now();
    vertex_step(counts);
    times.vertex = milliseconds_since(start);
    start = Clock::now();
    set_up_triangles(counts);
    times.setup = milliseconds_since(start);
    start = Clock::now();
    bin_triangles();
    times.binning = milliseconds_since(start);
    start = Clock::now();
    tile_step();
    times.tiles = milliseconds_since(start);
    for (const TileCounts& c : tile_counts) counts.tiles += c;
    return counts;
}

FrameCounts Renderer::render(const pipeline::Camera& camera) {
    Impl& s = *impl_;
    if (s.options.depth_only)
        throw std::logic_error("render: a depth_only renderer draws shadow maps (render_depth)");
    return s.timed_frame(
        times_, [&](FrameCounts& counts) { s.run_vertex_stage(camera, counts); },
        [&] { s.draw_tiles(frame_); });
}

FrameCounts Renderer::render_depth(const rl::mat4& view_projection, rl::FloatImage& depth) {
    Impl& s = *impl_;
    if (!s.options.depth_only)
        throw std::logic_error("render_depth: the renderer was not built with depth_only");
    if (depth.width() != s.width || depth.height() != s.height)
        throw std::invalid_argument("render_depth: the map's size is not the renderer's");
    return s.timed_frame(
        times_, [&](FrameCounts& counts) { s.run_depth_vertex_stage(view_projection, counts); },
        [&] { s.draw_depth_tiles(depth); });
}

OrbitRun render_orbit(Renderer& renderer, const pipeline::Camera& camera, int frames,
                      const std::function<void()>& between_frames) {
    std::vector<double> times, vertex, setup, binning, tiles;
    OrbitRun run;
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run.counts = renderer.render(orbit(camera, i, frames));
        times.push_back(milliseconds_since(start));
        const StageTimes& t = renderer.times();
        vertex.push_back(t.vertex), setup.push_back(t.setup), binning.push_back(t.binning);
        tiles.push_back(t.tiles);
        if (between_frames && i + 1 < frames) between_frames();
    }
    run.median_ms = median_after_first(std::move(times));
    run.median_stages = {
        median_after_first(std::move(vertex)), median_after_first(std::move(setup)),
        median_after_first(std::move(binning)), median_after_first(std::move(tiles))};
    return run;
}

}  // namespace fast
