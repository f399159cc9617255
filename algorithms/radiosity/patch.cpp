#include "radiosity/patch.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "core/step.hpp"

namespace cg {

using glm::dvec3;

namespace {
constexpr double kPi = 3.14159265358979323846;
// Coordinates beyond this are refused: areas and distances squared then stay finite.
constexpr double kMaxCoordinate = 1e100;

// |v| and v / |v| without squaring overflow or underflow (edges up to 1e100 make cross products
// up to 1e200, whose squares a double cannot hold).
double safe_length(const dvec3& v) {
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (m == 0 || !std::isfinite(m)) return m;
    return m * glm::length(v / m);
}
dvec3 safe_normalize(const dvec3& v) {
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    return glm::normalize(v / m);
}
}  // namespace

Patch Patch::rectangle(dvec3 corner, dvec3 u, dvec3 v) {
    return {Type::Rectangle, corner, u, v, 0};
}
Patch Patch::disc(dvec3 centre, dvec3 normal, double radius) {
    return {Type::Disc, centre, normal, dvec3(0), radius};
}
Patch Patch::triangle(dvec3 p0, dvec3 p1, dvec3 p2) {
    return {Type::Triangle, p0, p1, p2, 0};
}
Patch Patch::point(dvec3 centre, dvec3 normal) {
    return {Type::Point, centre, normal, dvec3(0), 0};
}

const char* type_name(Patch::Type t) {
    switch (t) {
        case Patch::Type::Rectangle:
            return "rectangle";
        case Patch::Type::Disc:
            return "disc";
        case Patch::Type::Triangle:
            return "triangle";
        case Patch::Type::Point:
            return "point";
    }
    return "?";
}

double area(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return safe_length(glm::cross(p.b, p.c));
        case Patch::Type::Disc:
            return kPi * p.radius * p.radius;
        case Patch::Type::Triangle:
            return 0.5 * safe_length(glm::cross(p.b - p.a, p.c - p.a));
        case Patch::Type::Point:
            return 0;
    }
    return 0;
}

dvec3 normal(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return safe_normalize(glm::cross(p.b, p.c));
        case Patch::Type::Disc:
        case Patch::Type::Point:
            return safe_normalize(p.b);
        case Patch::Type::Triangle:
            return safe_normalize(glm::cross(p.b - p.a, p.c - p.a));
    }
    return dvec3(0, 0, 1);
}

dvec3 centre(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return p.a + 0.5 * (p.b + p.c);
        case Patch::Type::Triangle:
            return (p.a + p.b + p.c) / 3.0;
        default:
            return p.a;
    }
}

double extent(const Patch& p) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return std::max(safe_length(p.b), safe_length(p.c));
        case Patch::Type::Disc:
            return 2 * p.radius;
        case Patch::Type::Triangle:
            return std::max(
                {safe_length(p.b - p.a), safe_length(p.c - p.b), safe_length(p.a - p.c)});
        case Patch::Type::Point:
            return 0;
    }
    return 0;
}

void tangents(const Patch& p, dvec3& t1, dvec3& t2) {
    const dvec3 n = normal(p);
    switch (p.type) {
        case Patch::Type::Rectangle:
            t1 = safe_normalize(p.b);
            break;
        case Patch::Type::Triangle:
            t1 = safe_normalize(p.b - p.a);
            break;
        default: {
            const dvec3 axis = std::fabs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
            t1 = glm::normalize(glm::cross(axis, n));
            break;
        }
    }
    t2 = glm::cross(n, t1);
}

dvec3 point_at(const Patch& p, double s, double t) {
    switch (p.type) {
        case Patch::Type::Rectangle:
            return p.a + s * p.b + t * p.c;
        case Patch::Type::Disc: {
            dvec3 t1, t2;
            tangents(p, t1, t2);
            const double r = p.radius * std::sqrt(s), phi = 2 * kPi * t;
            return p.a + r * (std::cos(phi) * t1 + std::sin(phi) * t2);
        }
        case Patch::Type::Triangle: {
            const double q = std::sqrt(s);  // uniform on the triangle (area-preserving)
            return (1 - q) * p.a + q * (1 - t) * p.b + q * t * p.c;
        }
        case Patch::Type::Point:
            return p.a;
    }
    return p.a;
}

std::optional<double> hit(const Patch& p, const dvec3& o, const dvec3& d, double eps) {
    if (p.type == Patch::Type::Point) return std::nullopt;
    dvec3 n;
    dvec3 origin = p.a;
    if (p.type == Patch::Type::Rectangle)
        n = glm::cross(p.b, p.c);
    else if (p.type == Patch::Type::Triangle)
        n = glm::cross(p.b - p.a, p.c - p.a);
    else
        n = p.b;
    const double dn = glm::dot(n, d);
    if (!(dn < 0)) return std::nullopt;  // parallel, or reaching the back side
    const double t = glm::dot(n, origin - o) / dn;
    if (!(t > eps) || !std::isfinite(t)) return std::nullopt;
    const dvec3 q = o + t * d - origin;
    switch (p.type) {
        case Patch::Type::Rectangle: {
            const double s = glm::dot(q, p.b) / glm::dot(p.b, p.b);
            const double r = glm::dot(q, p.c) / glm::dot(p.c, p.c);
            if (s >= 0 && s <= 1 && r >= 0 && r <= 1) return t;
            return std::nullopt;
        }
        case Patch::Type::Disc: {
            const dvec3 un = safe_normalize(n);
            const dvec3 inplane = q - glm::dot(q, un) * un;
            if (glm::dot(inplane, inplane) <= p.radius * p.radius) return t;
            return std::nullopt;
        }
        case Patch::Type::Triangle: {
            const dvec3 e1 = p.b - p.a, e2 = p.c - p.a;
            const double len = safe_length(n);
            const dvec3 un = n / len;
            const double w1 = glm::dot(glm::cross(q, e2), un) / len;  // weight of p1
            const double w2 = glm::dot(glm::cross(e1, q), un) / len;  // weight of p2
            if (w1 >= 0 && w2 >= 0 && w1 + w2 <= 1) return t;
            return std::nullopt;
        }
        case Patch::Type::Point:
            break;
    }
    return std::nullopt;
}

namespace {

void check_point(const dvec3& v, const std::string& field) {
    for (int i = 0; i < 3; ++i) {
        const std::string f = field + "[" + std::to_string(i) + "]";
        if (!std::isfinite(v[i]))
            throw InputError(f, "must be a finite number (got " + given(v[i]) + ")");
        if (std::fabs(v[i]) > kMaxCoordinate)
            throw InputError(f, "is too large (|" + given(v[i]) +
                                    "| > 1e100): areas and distances would overflow; scale the "
                                    "scene down");
    }
}

}  // namespace

void validate_patch(const Patch& p, const std::string& field, bool allow_point) {
    switch (p.type) {
        case Patch::Type::Rectangle: {
            check_point(p.a, field + ".corner");
            check_point(p.b, field + ".edge_u");
            check_point(p.c, field + ".edge_v");
            const double lu = safe_length(p.b), lv = safe_length(p.c);
            const double a = area(p);
            if (!(a > 0) || !(lu > 0) || !(lv > 0) || !std::isfinite(a))
                throw InputError(field,
                                 "the rectangle has zero area (edge_u × edge_v = 0): a "
                                 "form factor is per unit area of a patch");
            if (std::fabs(glm::dot(p.b, p.c)) > 1e-9 * lu * lv)
                throw InputError(field + ".edge_v",
                                 "must be perpendicular to edge_u (edge_u · edge_v = " +
                                     given(glm::dot(p.b, p.c)) +
                                     "): a rectangle, not a "
                                     "parallelogram");
            return;
        }
        case Patch::Type::Disc:
        case Patch::Type::Point: {
            const bool disc = p.type == Patch::Type::Disc;
            check_point(p.a, field + ".center");
            check_point(p.b, field + ".normal");
            if (p.b == dvec3(0)) throw InputError(field + ".normal", "must not be the zero vector");
            if (disc) {
                if (!std::isfinite(p.radius))
                    throw InputError(field + ".radius", "must be a finite number");
                if (p.radius > kMaxCoordinate)
                    throw InputError(field + ".radius",
                                     "is too large (> 1e100); scale the scene down");
                if (!(p.radius > 0) || !(area(p) > 0))
                    throw InputError(field + ".radius", "must be positive (got " + given(p.radius) +
                                                            "): a disc of radius 0 has zero area");
            } else if (!allow_point) {
                throw InputError(field,
                                 "a point (a differential area dA) can only be the patch a "
                                 "form factor starts from (\"from\"): rays cannot hit it");
            }
            return;
        }
        case Patch::Type::Triangle: {
            check_point(p.a, field + ".points[0]");
            check_point(p.b, field + ".points[1]");
            check_point(p.c, field + ".points[2]");
            const double a = area(p);
            if (!(a > 0) || !std::isfinite(a) || !std::isfinite(glm::length(normal(p))))
                throw InputError(field,
                                 "the triangle has zero area (its points are collinear or "
                                 "coincide): a form factor is per unit area of a patch");
            return;
        }
    }
}

}  // namespace cg
