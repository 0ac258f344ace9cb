#include "rasterlab/transform.hpp"

namespace rl {

mat3 rotation_x(float degrees) {
    const float a = radians(degrees), c = std::cos(a), s = std::sin(a);
    return {{vec3{1, 0, 0}, vec3{0, c, -s}, vec3{0, s, c}}};
}

mat3 rotation_y(float degrees) {
    const float a = radians(degrees), c = std::cos(a), s = std::sin(a);
    return {{vec3{c, 0, s}, vec3{0, 1, 0}, vec3{-s, 0, c}}};
}

mat3 rotation_z(float degrees) {
    const float a = radians(degrees), c = std::cos(a), s = std::sin(a);
    return {{vec3{c, -s, 0}, vec3{s, c, 0}, vec3{0, 0, 1}}};
}

Quaternion axis_angle(vec3 axis, float degrees) {
    const vec3 n = normalize(axis);
    const float half = 0.5f * radians(degrees), s = std::sin(half);
    return {std::cos(half), n.x * s, n.y * s, n.z * s};
}

Quaternion operator*(const Quaternion& a, const Quaternion& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

mat3 to_matrix(const Quaternion& q) {
    const float x = q.x, y = q.y, z = q.z, w = q.w;
    return {{vec3{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
             vec3{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
             vec3{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
}

Quaternion to_quaternion(const mat3& m) {
    // Shepperd's method: divide by the largest of 4w^2, 4x^2, 4y^2, 4z^2,
    // which the diagonal gives, so that no division is by a small number.
    const float trace = m[0][0] + m[1][1] + m[2][2];
    Quaternion q;
    if (trace > 0) {
        const float s = 2 * std::sqrt(trace + 1);
        q = {s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
    } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        const float s = 2 * std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
        q = {(m[2][1] - m[1][2]) / s, s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
    } else if (m[1][1] > m[2][2]) {
        const float s = 2 * std::sqrt(1 + m[1][1] - m[0][0] - m[2][2]);
        q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s};
    } else {
        const float s = 2 * std::sqrt(1 + m[2][2] - m[0][0] - m[1][1]);
        q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4};
    }
    return q;
}

mat4 compose(const Trs& trs) {
    const mat3 r = to_matrix(trs.rotation);
    mat4 m = mat4::identity();
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) m[i][j] = r[i][j] * trs.scale[j];  // R * diag(scale)
        m[i][3] = trs.translation[i];
    }
    return m;
}

std::optional<Trs> decompose(const mat4& m, float tolerance) {
    if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1) return std::nullopt;
    Trs trs;
    mat3 r;
    for (std::size_t j = 0; j < 3; ++j) {
        const vec3 column{m[0][j], m[1][j], m[2][j]};
        trs.scale[j] = length(column);
        if (!(trs.scale[j] > tolerance)) return std::nullopt;  // singular (or NaN)
        for (std::size_t i = 0; i < 3; ++i) r[i][j] = column[i] / trs.scale[j];
        trs.translation[j] = m[j][3];
    }
    if (determinant(r) < 0) {  // a reflection: carry it in the x scale
        trs.scale.x = -trs.scale.x;
        for (std::size_t i = 0; i < 3; ++i) r[i][0] = -r[i][0];
    }
    const mat3 should_be_identity = transpose(r) * r;
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j)
            if (std::abs(should_be_identity[i][j] - (i == j ? 1.0f : 0.0f)) > tolerance)
                return std::nullopt;  // sheared: not a rotation times a scale
    trs.rotation = to_quaternion(r);
    return trs;
}

std::optional<mat4> look_at(vec3 eye, vec3 target, vec3 up) {
    const vec3 towards = target - eye;
    if (towards == vec3{}) return std::nullopt;
    const vec3 f = normalize(towards), up_direction = normalize(up);
    const vec3 side = cross(f, up_direction);
    if (!(length(side) > 1e-6f)) return std::nullopt;  // up along the view (or zero, or NaN)
    const vec3 s = normalize(side), u = cross(s, f);
    return mat4{{vec4{s.x, s.y, s.z, -dot(s, eye)}, vec4{u.x, u.y, u.z, -dot(u, eye)},
                 vec4{-f.x, -f.y, -f.z, dot(f, eye)}, vec4{0, 0, 0, 1}}};
}

mat4 perspective(float fov_y_degrees, float aspect, float near, float far) {
    const float f = 1.0f / std::tan(0.5f * radians(fov_y_degrees));
    return mat4{{vec4{f / aspect, 0, 0, 0}, vec4{0, f, 0, 0},
                 vec4{0, 0, (far + near) / (near - far), 2 * far * near / (near - far)},
                 vec4{0, 0, -1, 0}}};
}

vec3 ndc_to_window(vec3 ndc, int width, int height) {
    return {(ndc.x + 1) * 0.5f * static_cast<float>(width),
            (ndc.y + 1) * 0.5f * static_cast<float>(height), (ndc.z + 1) * 0.5f};
}

}  // namespace rl
