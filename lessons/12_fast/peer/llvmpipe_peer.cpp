#include "llvmpipe_peer.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "12_fast/renderer.hpp"

namespace fast {

namespace {

// Lesson 07's NormalMappedShader in GLSL: the vertex function, then
// normal_at(), reflection() and surface_colour(), and lesson 06's encode().
const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 tangent;
layout(location = 3) in vec2 uv;
uniform mat4 model_view_projection, model_matrix;
uniform mat3 normal_matrix;
uniform float mirror;
out vec3 v_position, v_normal, v_tangent;
out float v_handedness;
out vec2 v_uv;
void main() {
    gl_Position = model_view_projection * vec4(position, 1.0);
    v_position = (model_matrix * vec4(position, 1.0)).xyz;
    v_normal = normalize(normal_matrix * normal);
    v_tangent = (model_matrix * vec4(tangent.xyz, 0.0)).xyz;
    v_handedness = tangent.w * mirror;
    v_uv = uv;
}
)";

const char* const kFragmentShader = R"(#version 330 core
in vec3 v_position, v_normal, v_tangent;
in float v_handedness;
in vec2 v_uv;
uniform sampler2D albedo_map, normal_map, specular_map;
uniform int normal_source;  // 0 interpolated, 1 tangent-space map, 2 object-space map
uniform bool has_specular_map, blinn, srgb;
uniform mat3 normal_matrix;
uniform vec3 eye, ambient, specular_colour;
uniform float shininess;
uniform int lights;
uniform vec3 light_direction[8], light_colour[8];
out vec4 colour;
float highlight(float alignment) {
    float base = max(alignment, 0.0);
    return base > 0.0 ? pow(base, shininess) : (shininess == 0.0 ? 1.0 : 0.0);
}
float encode(float c) {
    if (!srgb) return clamp(c, 0.0, 1.0);
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? c * 12.92 : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}
void main() {
    vec3 n = normalize(v_normal);
    if (normal_source != 0) {
        vec3 m = 2.0 * texture(normal_map, v_uv).rgb - 1.0;
        float len = length(m);
        if (len >= 2.0 / 255.0) {
            if (normal_source == 1) {
                vec3 t = normalize(v_tangent - n * dot(n, v_tangent));
                vec3 b = cross(n, t) * (v_handedness < 0.0 ? -1.0 : 1.0);
                n = (t * m.x + b * m.y + n * m.z) / len;
            } else {
                n = normalize(normal_matrix * m);
            }
        }
    }
    vec3 to_eye = normalize(eye - v_position);
    vec3 diffuse = ambient, specular = vec3(0.0);
    for (int i = 0; i < lights; ++i) {
        vec3 l = light_direction[i];
        float n_dot_l = dot(n, l);
        if (!(n_dot_l > 0.0)) continue;
        float s = blinn ? dot(n, normalize(l + to_eye)) : dot(n * (2.0 * n_dot_l) - l, to_eye);
        diffuse += light_colour[i] * n_dot_l;
        specular += light_colour[i] * specular_colour * highlight(s);
    }
    float peak = max(specular.r, max(specular.g, specular.b));
    float shine = !has_specular_map ? 1.0 : (peak < 1e-4 ? 0.0 : texture(specular_map, v_uv).r);
    vec3 c = texture(albedo_map, v_uv).rgb * diffuse + specular * shine;
    colour = vec4(encode(c.r), encode(c.g), encode(c.b), 1.0);
}
)";

// The plain peer's fragment shader: one light, Phong, the colour map.
const char* const kPlainFragmentShader = R"(#version 330 core
in vec3 v_position, v_normal;
in vec2 v_uv;
uniform sampler2D albedo_map;
uniform vec3 eye, ambient, specular_colour;
uniform float shininess;
uniform vec3 light_direction[8], light_colour[8];
out vec4 colour;
void main() {
    vec3 n = normalize(v_normal);
    vec3 l = light_direction[0];
    float n_dot_l = max(dot(n, l), 0.0);
    float s = n_dot_l > 0.0
        ? pow(max(dot(reflect(-l, n), normalize(eye - v_position)), 0.0), shininess) : 0.0;
    vec3 c = texture(albedo_map, v_uv).rgb * (ambient + light_colour[0] * n_dot_l) +
             specular_colour * light_colour[0] * s;
    colour = vec4(clamp(c, 0.0, 1.0), 1.0);
}
)";

GLuint compile(GLenum kind, const char* source) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("llvmpipe peer: a shader does not compile: ") + log);
    }
    return shader;
}

// A texture's levels, exactly lesson 04's, uploaded one by one.
GLuint upload_texture(const textures::MipChain& chain, bool srgb, bool all_levels) {
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    const int levels = all_levels ? chain.levels() : 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int i = 0; i < levels; ++i) {
        const rl::Image& level = chain.level(i);
        glTexImage2D(GL_TEXTURE_2D, i, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, level.width(),
                     level.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, level.pixels().data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return name;
}

void set_filter(textures::Filter filter) {
    const GLint min = filter == textures::Filter::trilinear  ? GL_LINEAR_MIPMAP_LINEAR
                      : filter == textures::Filter::bilinear ? GL_LINEAR
                                                             : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                    filter == textures::Filter::nearest ? GL_NEAREST : GL_LINEAR);
}

struct GpuModel {
    const normal_mapping::MappedModel* source = nullptr;
    GLuint vertex_array = 0, buffers[2] = {0, 0};
    GLsizei indices = 0;
    GLuint albedo = 0, normal_map = 0, specular_map = 0;
    int normal_source = 0;
    bool mirrored = false;
    std::optional<rl::mat3> normal_matrix;
};

}  // namespace

struct LlvmpipePeer::Impl {
    int width, height;
    OSMesaContext context = nullptr;
    std::vector<std::uint8_t> buffer;  // the default framebuffer, RGBA
    GLuint program = 0;
    std::vector<GpuModel> models;
    normal_mapping::RenderOptions options;
    GLint location(const char* name) const { return glGetUniformLocation(program, name); }
};

LlvmpipePeer::LlvmpipePeer(int width, int height, int threads, PeerShader shader)
    : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.width = width, s.height = height;
    // llvmpipe reads its thread count when its first context is made.
    setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    s.context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!s.context) throw PeerUnavailable("OSMesa made no OpenGL 3.3 core context");
    s.buffer.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    if (!OSMesaMakeCurrent(s.context, s.buffer.data(), GL_UNSIGNED_BYTE, width, height))
        throw PeerUnavailable("OSMesa could not draw into a " + std::to_string(width) + "x" +
                              std::to_string(height) + " buffer");
    const GLuint vertex = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fragment = compile(
        GL_FRAGMENT_SHADER, shader == PeerShader::plain ? kPlainFragmentShader : kFragmentShader);
    s.program = glCreateProgram();
    glAttachShader(s.program, vertex);
    glAttachShader(s.program, fragment);
    glLinkProgram(s.program);
    GLint ok = 0;
    glGetProgramiv(s.program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("llvmpipe peer: the shaders do not link");
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
}

LlvmpipePeer::~LlvmpipePeer() {
    if (impl_->context) OSMesaDestroyContext(impl_->context);
}

void LlvmpipePeer::upload(const std::vector<normal_mapping::MappedModel>& models,
                          const normal_mapping::RenderOptions& options) {
    Impl& s = *impl_;
    s.options = options;
    FastOptions indexing;
    indexing.render = options;
    const bool all_levels = options.filter == textures::Filter::trilinear;
    const bool srgb = options.output == shading::Output::srgb;
    for (const normal_mapping::MappedModel& m : models) {
        GpuModel g;
        g.source = &m;
        const FastModel fm = fast_model(m, indexing);
        const rl::Mesh& mesh = m.lit.model.mesh;
        // position, normal, tangent, uv: 12 floats a vertex
        std::vector<float> vertices;
        vertices.reserve(fm.representative.size() * 12);
        for (std::uint32_t corner : fm.representative) {
            const rl::Face& face = mesh.faces[corner / 3];
            const int k = static_cast<int>(corner % 3);
            const rl::vec3 p = mesh.position(face, k);
            const rl::vec3 n = m.lit.normals[corner];
            const rl::vec4 t = m.tangents[corner];
            const int uv = face.corners[static_cast<std::size_t>(k)].uv;
            const rl::vec2 tex = uv >= 0 ? mesh.uvs[static_cast<std::size_t>(uv)] : rl::vec2{};
            for (float f : {p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y, t.z, t.w, tex.x, tex.y})
                vertices.push_back(f);
        }
        glGenVertexArrays(1, &g.vertex_array);
        glBindVertexArray(g.vertex_array);
        glGenBuffers(2, g.buffers);
        glBindBuffer(GL_ARRAY_BUFFER, g.buffers[0]);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                     vertices.data(), GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.buffers[1]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(fm.indices.size() * sizeof(std::uint32_t)),
                     fm.indices.data(), GL_STATIC_DRAW);
        const GLsizei stride = 12 * sizeof(float);
        const int sizes[4] = {3, 3, 4, 2}, offsets[4] = {0, 3, 6, 10};
        for (GLuint a = 0; a < 4; ++a) {
            glEnableVertexAttribArray(a);
            glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(offsets[a] * sizeof(float)));
        }
        g.indices = static_cast<GLsizei>(fm.indices.size());
        g.albedo = upload_texture(m.lit.model.texture, srgb, all_levels);
        set_filter(options.filter);
        const textures::MipChain* normal_map = nullptr;
        if (options.normal_map == normal_mapping::NormalMap::tangent && m.maps.tangent_normals)
            normal_map = &*m.maps.tangent_normals, g.normal_source = 1;
        else if (options.normal_map == normal_mapping::NormalMap::object && m.maps.object_normals)
            normal_map = &*m.maps.object_normals, g.normal_source = 2;
        if (normal_map) {
            g.normal_map = upload_texture(*normal_map, false, all_levels);
            set_filter(options.filter);
        }
        if (m.maps.specular) {
            g.specular_map = upload_texture(*m.maps.specular, false, all_levels);
            set_filter(options.filter);
        }
        g.mirrored = rl::determinant(rl::linear_part(m.lit.model.transform)) < 0;
        g.normal_matrix = shading::normal_matrix(m.lit.model.transform);
        s.models.push_back(g);
    }
    glFinish();
}

double LlvmpipePeer::render(const pipeline::Camera& camera) {
    Impl& s = *impl_;
    const auto start = std::chrono::steady_clock::now();
    const float aspect = static_cast<float>(s.width) / static_cast<float>(s.height);
    const rl::mat4 view_projection = pipeline::view_projection(camera, aspect);
    const rl::Rgba b = rl::kBackground;
    glClearColor(b.r / 255.0f, b.g / 255.0f, b.b / 255.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(s.program);
    const shading::Lighting<float>& lighting = s.options.lighting;
    const int lights = static_cast<int>(std::min<std::size_t>(lighting.lights.size(), 8));
    glUniform1i(s.location("lights"), lights);
    for (int i = 0; i < lights; ++i) {
        const shading::Light<float>& l = lighting.lights[static_cast<std::size_t>(i)];
        char direction[32], colour[32];
        std::snprintf(direction, sizeof direction, "light_direction[%d]", i);
        std::snprintf(colour, sizeof colour, "light_colour[%d]", i);
        glUniform3f(s.location(direction), l.direction.x, l.direction.y, l.direction.z);
        glUniform3f(s.location(colour), l.colour.x, l.colour.y, l.colour.z);
    }
    glUniform3f(s.location("ambient"), lighting.ambient.x, lighting.ambient.y, lighting.ambient.z);
    glUniform3f(s.location("specular_colour"), lighting.specular.x, lighting.specular.y,
                lighting.specular.z);
    glUniform1f(s.location("shininess"), lighting.shininess);
    glUniform1i(s.location("blinn"), s.options.specular == shading::Specular::blinn_phong);
    glUniform1i(s.location("srgb"), s.options.output == shading::Output::srgb);
    glUniform3f(s.location("eye"), camera.eye.x, camera.eye.y, camera.eye.z);
    glUniform1i(s.location("albedo_map"), 0);
    glUniform1i(s.location("normal_map"), 1);
    glUniform1i(s.location("specular_map"), 2);
    for (const GpuModel& g : s.models) {
        if (!g.normal_matrix) continue;
        const rl::mat4& model = g.source->lit.model.transform;
        const rl::mat4 mvp = view_projection * model;
        if (s.options.cull_objects && pipeline::outside_frustum(g.source->lit.model.box, mvp))
            continue;
        // rl matrices are row-major: GL_TRUE transposes them into GL's order.
        glUniformMatrix4fv(s.location("model_view_projection"), 1, GL_TRUE, &mvp[0][0]);
        glUniformMatrix4fv(s.location("model_matrix"), 1, GL_TRUE, &model[0][0]);
        glUniformMatrix3fv(s.location("normal_matrix"), 1, GL_TRUE, &(*g.normal_matrix)[0][0]);
        glUniform1f(s.location("mirror"), g.mirrored ? -1.0f : 1.0f);
        glUniform1i(s.location("normal_source"), g.normal_source);
        glUniform1i(s.location("has_specular_map"), g.specular_map != 0);
        glFrontFace(g.mirrored ? GL_CW : GL_CCW);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, g.albedo);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, g.normal_map);
        glActiveTexture(GL_TEXTURE2);
        glBindTexture(GL_TEXTURE_2D, g.specular_map);
        glBindVertexArray(g.vertex_array);
        glDrawElements(GL_TRIANGLES, g.indices, GL_UNSIGNED_INT, nullptr);
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

rl::Image LlvmpipePeer::frame() const {
    const Impl& s = *impl_;
    rl::Image out(s.width, s.height);
    // OSMesa's buffer holds rows bottom first (its default Y_UP), as rl::Image does.
    std::memcpy(static_cast<void*>(out.pixels().data()), s.buffer.data(), s.buffer.size());
    return out;
}

std::string LlvmpipePeer::version() const {
    const auto text = [](GLenum what) {
        const GLubyte* s = glGetString(what);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return text(GL_VERSION) + ", " + text(GL_RENDERER);
}

}  // namespace fast
