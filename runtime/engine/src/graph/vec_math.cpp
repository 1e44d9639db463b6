#include "g2d/vec_math.hpp"

#include <cmath>

namespace g2d::rt {

double dot(vec2 a, vec2 b) { return a.x * b.x + a.y * b.y; }
double cross(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }
double length(vec2 v) { return std::hypot(v.x, v.y); }
double distance(vec2 a, vec2 b) { return length(b - a); }

vec2 normalize(vec2 v) {
    const double l = length(v);
    return l > 0 ? v / l : vec2(0.0, 0.0);
}

vec2 perpLeft(vec2 v) { return {-v.y, v.x}; }
vec2 perpRight(vec2 v) { return {v.y, -v.x}; }

vec2 rotate(vec2 v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

vec2 rotateAround(vec2 v, double a, vec2 centre) { return centre + rotate(v - centre, a); }

double angle(vec2 v) { return std::atan2(v.y, v.x); }
double angleBetween(vec2 a, vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }

vec2 lerp(vec2 a, vec2 b, double t) { return a + (b - a) * t; }
double lerp(double a, double b, double t) { return a + (b - a) * t; }

double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
vec3 cross(vec3 a, vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(vec3 v) { return std::sqrt(dot(v, v)); }
double distance(vec3 a, vec3 b) { return length(b - a); }

vec3 normalize(vec3 v) {
    const double l = length(v);
    return l > 0 ? v / l : vec3(0.0, 0.0, 0.0);
}

vec3 lerp(vec3 a, vec3 b, double t) { return a + (b - a) * t; }

vec3 rotateAxis(vec3 v, vec3 axis, double a) {
    const vec3 k = normalize(axis);
    if (k == vec3(0.0, 0.0, 0.0)) return v;
    const double c = std::cos(a), s = std::sin(a);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

double fmodFloor(double a, double b) {
    const double r = std::fmod(a, b);
    return (r != 0 && ((r < 0) != (b < 0))) ? r + b : r;
}

long long imodFloor(long long a, long long b) {
    const long long r = a % b;
    return (r != 0 && ((r < 0) != (b < 0))) ? r + b : r;
}

double roundHalfAway(double x) { return std::round(x); }

}  // namespace g2d::rt
