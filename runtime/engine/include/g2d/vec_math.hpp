#pragma once
// Vector and scalar functions of the language, shared by the constant folder,
// the interpreter and generated code so that all agree to the last bit.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace g2d::rt {

using vec2 = glm::dvec2;
// 3D positions and directions (grammars declared `space 3d;`, G^3).
using vec3 = glm::dvec3;

double dot(vec2 a, vec2 b);
double cross(vec2 a, vec2 b);            // z of the 3D cross product: a.x*b.y - a.y*b.x
double length(vec2 v);
double distance(vec2 a, vec2 b);
vec2 normalize(vec2 v);                  // the zero vector stays zero
vec2 perpLeft(vec2 v);                   // (-y, x): 90° counter-clockwise
vec2 perpRight(vec2 v);                  // (y, -x): 90° clockwise
vec2 rotate(vec2 v, double radians);     // counter-clockwise about the origin
vec2 rotateAround(vec2 v, double radians, vec2 centre);
double angle(vec2 v);                    // atan2(y, x), in (-pi, pi]
double angleBetween(vec2 a, vec2 b);     // signed angle from a to b, in (-pi, pi]
vec2 lerp(vec2 a, vec2 b, double t);
double lerp(double a, double b, double t);

double dot(vec3 a, vec3 b);
vec3 cross(vec3 a, vec3 b);
double length(vec3 v);
double distance(vec3 a, vec3 b);
vec3 normalize(vec3 v);                  // the zero vector stays zero
vec3 lerp(vec3 a, vec3 b, double t);
// Rotation of v by `radians` about `axis` through the origin, counter-clockwise
// looking down the axis (right-handed; Rodrigues' formula). A zero axis
// leaves v as it is.
vec3 rotateAxis(vec3 v, vec3 axis, double radians);

// Floored modulo (the sign follows the divisor), as in the language's `%`.
double fmodFloor(double a, double b);
long long imodFloor(long long a, long long b);
double roundHalfAway(double x);          // round(): halves away from zero

}  // namespace g2d::rt
