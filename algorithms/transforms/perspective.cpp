// Sections: [helpers] [spec] [validate] [advance] [narrate] [project]; the picture is in
// perspective_draw.cpp
#include "transforms/perspective.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/format.hpp"

namespace cg {

namespace {

using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using Convention = Perspective::Convention;
using Phase = Perspective::Phase;
using Status = Perspective::SegmentStatus;

constexpr double kPi = 3.14159265358979323846;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineModel = 1,
    kLineView,
    kLineProjection,
    kLinePointView,
    kLinePointClip,
    kLinePointDivide,
    kLinePointDevice,
    kLineSegmentClip,
    kLineSegmentDivide,
};

// The view frame's z axis is +f̂ (course) or −f̂ (opengl); the matrix's w row is ±z likewise.
double zsign(Convention c) { return c == Convention::Course ? 1.0 : -1.0; }

struct Frame {
    dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1}, eye{0, 0, 0};
};

Frame view_frame(const Perspective::Input& in) {
    Frame f;
    if (!in.look_at) {  // the points are in view coordinates already
        f.forward = {0, 0, zsign(in.convention)};
        return f;
    }
    f.eye = in.eye;
    f.forward = glm::normalize(in.center - in.eye);
    f.right = glm::normalize(glm::cross(f.forward, in.up));
    f.up = glm::cross(f.right, f.forward);
    return f;
}

dvec3 apply_affine(const dmat4& m, dvec3 p) { return dvec3(m * dvec4(p, 1.0)); }

bool finite(dvec4 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}
bool finite(const dmat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(m[c])) return false;
    return true;
}

bool in_volume(dvec4 c) {
    return c.w > 0 && -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && -c.w <= c.z &&
           c.z <= c.w;
}

// The near plane in clip space: d = z + w ≥ 0 on the kept side (d = 2f(depth − n)/(f − n)).
double near_distance(dvec4 c) { return c.z + c.w; }

std::vector<std::vector<double>> rows(const dmat4& m) {
    std::vector<std::vector<double>> r(4);
    for (int i = 0; i < 4; ++i) r[i] = {m[0][i], m[1][i], m[2][i], m[3][i]};
    return r;
}

std::vector<double> vec4(dvec4 v) { return {v.x, v.y, v.z, v.w}; }

std::string num4(dvec4 v, int digits = 4) {
    return "(" + num(v.x, digits) + ", " + num(v.y, digits) + ", " + num(v.z, digits) + ", " +
           num(v.w, digits) + ")";
}

std::string matrix_text(const dmat4& m) {
    std::string t = "[";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) t += (c ? " " : "") + num(m[c][r], 4);
        t += r < 3 ? "; " : "]";
    }
    return t;
}

std::string matrix_tex(const dmat4& m) {
    std::string t = "\\begin{bmatrix} ";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) t += (c ? " & " : "") + tex(m[c][r], 4);
        t += r < 3 ? " \\\\ " : " \\end{bmatrix}";
    }
    return t;
}

std::string column_tex(dvec4 v) {
    return "\\begin{bmatrix} " + tex(v.x, 4) + " \\\\ " + tex(v.y, 4) + " \\\\ " + tex(v.z, 4) +
           " \\\\ " + tex(v.w, 4) + " \\end{bmatrix}";
}

void check_finite(double v, const std::string& field) {
    if (!std::isfinite(v)) throw InputError(field, "must be a finite number (got " + given(v) + ")");
}
void check_finite(dvec3 p, const std::string& field) {
    check_finite(p.x, field + "[0]");
    check_finite(p.y, field + "[1]");
    check_finite(p.z, field + "[2]");
}

std::string point_name(int k) { return "P" + std::to_string(k); }
std::string segment_name(int k) { return "segment " + std::to_string(k); }

// The clip coordinates of a model point, through the three matrices in turn.
struct Through {
    dvec3 world, view;
    dvec4 clip;
};
Through through(const Perspective::Result& r, dvec3 p) {
    Through t;
    t.world = apply_affine(r.model, p);
    t.view = apply_affine(r.view, t.world);
    t.clip = r.projection * dvec4(t.view, 1.0);
    return t;
}

// Clips the segment a → b (clip coordinates) against the near plane z + w ≥ 0.
Perspective::Segment clip_near(dvec4 a, dvec4 b) {
    Perspective::Segment s;
    s.clip = {a, b};
    const double da = near_distance(a), db = near_distance(b);
    if (da >= 0 && db >= 0) {
        s.status = Status::Inside;
        s.kept = {a, b};
    } else if (da < 0 && db < 0) {
        s.status = Status::Rejected;
        s.t0 = s.t1 = 0;
        return s;
    } else {
        s.status = Status::Clipped;
        const double t = da / (da - db);
        dvec4 cut = a + t * (b - a);
        cut.z = -cut.w;  // on the plane exactly: z_ndc = −1
        if (da < 0) {
            s.t0 = t;
            s.kept = {cut, b};
        } else {
            s.t1 = t;
            s.kept = {a, cut};
        }
    }
    for (int e = 0; e < 2; ++e) s.ndc[e] = dvec3(s.kept[e]) / s.kept[e].w;
    return s;
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& Perspective::spec() {
    static const Spec spec{
        "perspective",
        "The projection pipeline: model, world, view, clip, NDC, viewport",
        "Perspective Projection",
        {
            "M_model: model → world (the identity unless given)",
            "V ← look-at: f̂ = (center − eye)/|…|, r = f̂ × up/|…|, u = r × f̂; rows r, u, ±f̂",
            "P ← [c/a 0 0 0; 0 c 0 0; 0 0 ±(f+n)/(f−n) −2fn/(f−n); 0 0 ±1 0],  c = cot(θ/2)  "
            "(frustum l, r, b, t: [2n/(r−l) 0 ∓(r+l)/(r−l) 0; 0 2n/(t−b) ∓(t+b)/(t−b) 0; …])",
            "for each point p:  p_view ← V M_model p",
            "  p_clip ← P p_view         ▷ inside the volume iff −w ≤ x, y, z ≤ w",
            "  if w > 0: p_ndc ← (x/w, y/w, z/w)   ▷ the perspective divide",
            "  p_device ← ((x_ndc + 1) W/2, (y_ndc + 1) H/2)",
            "for each segment AB: keep d = z + w ≥ 0, cut at t = d_A/(d_A − d_B)  ▷ near plane",
            "  divide the kept part's endpoints",
        },
        {
            {"model-matrix", "the model matrix taking the points into the world"},
            {"view-frame", "the look-at frame and the view matrix"},
            {"view-identity", "no look-at given: the points are in view coordinates already"},
            {"projection-matrix", "the perspective matrix for the field of view, aspect, near, far "
                                  "(or the frustum's left, right, bottom, top, near, far)"},
            {"point-to-view", "one point through the model and view matrices"},
            {"inside-volume", "the point's clip coordinates satisfy −w ≤ x, y, z ≤ w"},
            {"outside-volume", "the point is in front of the eye but outside the view volume"},
            {"behind-eye", "w ≤ 0: the point is at or behind the eye"},
            {"divide", "the perspective divide: NDC = (x/w, y/w, z/w)"},
            {"no-divide", "w ≤ 0: dividing would put the point on the wrong side"},
            {"to-viewport", "NDC to pixels"},
            {"segment-kept", "both ends beyond the near plane: the segment is kept whole"},
            {"segment-clipped", "the segment crosses the near plane: cut in clip space"},
            {"segment-rejected", "both ends in front of the near plane: discarded"},
            {"segment-divide", "the kept part's endpoints divided to NDC"},
        },
        {},  // no sliders
        {
            .predict = {
                {"projection-matrix", {"P"}},
                {"inside-volume", {"p_clip"}},
                {"outside-volume", {"p_clip"}},
                {"divide", {"p_ndc"}},
                {"to-viewport", {"p_device"}},
                {"segment-clipped", {"t0", "t1"}},
            },
            .mistakes = {
                {"projection-matrix", "P", "transpose", "wrote the projection matrix transposed"},
                {"outside-volume", "", "event:inside-volume",
                 "checked x and y against w but not z"},
                {"behind-eye", "", "event:outside-volume", "missed w < 0 and divided anyway"},
                {"segment-clipped", "d_A", "negate",
                 "took A's distance to the plane with the wrong sign"},
            },
            .variants = {
                {"course", "/convention", "\"course\""},
                {"opengl", "/convention", "\"opengl\""},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

dmat4 Perspective::projection_matrix(const Input& in) {
    if (in.has_frustum) {  // glFrustum; the course's convention negates the third column
        const double n = in.near, f = in.far, s = zsign(in.convention);
        const double w = in.right - in.left, h = in.top - in.bottom;
        dmat4 m(0.0);
        m[0][0] = 2 * n / w;
        m[1][1] = 2 * n / h;
        m[2][0] = -s * (in.right + in.left) / w;
        m[2][1] = -s * (in.top + in.bottom) / h;
        m[2][2] = s * (f + n) / (f - n);
        m[3][2] = -2 * f * n / (f - n);
        m[2][3] = s;
        return m;
    }
    // cot(θ/2) = sin(90° − θ/2) / sin(θ/2): exactly 1 for θ = 90°, where 1/tan(π/4) and
    // cos(π/4)/sin(π/4) are 1 + 2⁻⁵² (the sines of equal arguments are equal).
    const double half = in.fov_y_deg / 2;
    const double c = std::sin((90 - half) * kPi / 180) / std::sin(half * kPi / 180);
    const double n = in.near, f = in.far, s = zsign(in.convention);
    dmat4 m(0.0);  // glm is m[column][row]
    m[0][0] = c / in.aspect;
    m[1][1] = c;
    m[2][2] = s * (f + n) / (f - n);
    m[3][2] = -2 * f * n / (f - n);
    m[2][3] = s;
    return m;
}

namespace {

// The view matrix of a look-at frame: rows r, u, ±f̂, each with translation −row · eye.
dmat4 view_from(const Frame& fr, Convention convention) {
    const dvec3 z = zsign(convention) * fr.forward;
    dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = fr.right[c];
        m[c][1] = fr.up[c];
        m[c][2] = z[c];
    }
    m[3][0] = -glm::dot(fr.right, fr.eye);
    m[3][1] = -glm::dot(fr.up, fr.eye);
    m[3][2] = -glm::dot(z, fr.eye);
    return m;
}

}  // namespace

dmat4 Perspective::view_matrix(const Input& in) {
    return in.look_at ? view_from(view_frame(in), in.convention) : dmat4(1.0);
}

namespace {

// The off-axis frustum's own checks: finite, left < right, bottom < top, and a width and
// height whose entries 2n/(r − l), (r + l)/(r − l) (and for t, b) are finite and non-zero.
void validate_frustum(const Perspective::Input& in) {
    check_finite(in.left, "frustum.left");
    check_finite(in.right, "frustum.right");
    check_finite(in.bottom, "frustum.bottom");
    check_finite(in.top, "frustum.top");
    if (!(in.left < in.right))
        throw InputError("frustum.right", "must be greater than left (" + given(in.right) + " ≤ " +
                                              given(in.left) + "): the near rectangle has no width");
    if (!(in.bottom < in.top))
        throw InputError("frustum.top", "must be greater than bottom (" + given(in.top) + " ≤ " +
                                            given(in.bottom) + "): the near rectangle has no height");
    auto usable = [&](double lo, double hi) {
        const double w = hi - lo, a = 2 * in.near / w, b = (hi + lo) / w;
        return std::isfinite(w) && std::isfinite(a) && std::isfinite(b) && a != 0;
    };
    if (!usable(in.left, in.right))
        throw InputError("frustum.right", "left " + given(in.left) + " and right " + given(in.right) +
                                              " give a matrix too large or too small to use "
                                              "for near " + given(in.near));
    if (!usable(in.bottom, in.top))
        throw InputError("frustum.top", "bottom " + given(in.bottom) + " and top " + given(in.top) +
                                            " give a matrix too large or too small to use "
                                            "for near " + given(in.near));
}

}  // namespace

void Perspective::validate(const Input& in) {
    // In the frustum form, near and far are fields of "frustum".
    const std::string near_field = in.has_frustum ? "frustum.near" : "near";
    const std::string far_field = in.has_frustum ? "frustum.far" : "far";
    if (!in.has_frustum) {
        check_finite(in.fov_y_deg, "fov_y_deg");
        check_finite(in.aspect, "aspect");
    }
    check_finite(in.near, near_field);
    check_finite(in.far, far_field);
    if (!in.has_frustum) {
        if (!(in.fov_y_deg > 0 && in.fov_y_deg < 180))
            throw InputError("fov_y_deg", "must be between 0 and 180 degrees, both excluded (got " +
                                              given(in.fov_y_deg) + ")");
        if (in.aspect <= 0)
            throw InputError("aspect", "must be positive: it is width / height (got " +
                                           given(in.aspect) + ")");
    }
    if (in.near <= 0)
        throw InputError(near_field,
                         "must be positive: the near plane lies in front of the eye (got " +
                             given(in.near) + ")");
    // Beyond these the matrix's entries (far + near)/(far − near) and 2 far near/(far − near)
    // lose all precision or overflow, and near is the first of the two a user puts out of range.
    if (in.near < 1e-100 || in.near > 1e100)
        throw InputError(near_field, "must lie between 1e-100 and 1e100 (got " + given(in.near) + ")");
    if (in.far <= in.near)
        throw InputError(far_field, "must be greater than near (" + given(in.far) +
                                        " ≤ " + given(in.near) + ")");
    if (in.has_frustum) validate_frustum(in);
    if (!finite(projection_matrix(in)) || projection_matrix(in)[0][0] == 0)
        throw InputError(far_field, "near " + given(in.near) + " and far " + given(in.far) +
                                        " give a matrix too large or too small to use");
    if (in.look_at) {
        check_finite(in.eye, "eye");
        check_finite(in.center, "center");
        check_finite(in.up, "up");
        const dvec3 dir = in.center - in.eye;
        if (dir == dvec3(0))
            throw InputError("center", "must differ from eye " + given(in.eye) +
                                           ": the view direction center − eye is zero");
        if (in.up == dvec3(0)) throw InputError("up", "must not be the zero vector");
        if (!std::isfinite(glm::length(dir)) || !std::isfinite(glm::length(in.up)))
            throw InputError(!std::isfinite(glm::length(dir)) ? "center" : "up",
                             "is too large to normalise");
        const double sine = glm::length(glm::cross(dir / glm::length(dir), in.up / glm::length(in.up)));
        if (sine < 1e-9)
            throw InputError("up", "must not be parallel to the view direction center − eye = " +
                                       given(dir) + " (got " + given(in.up) +
                                       "): the camera's roll is undefined");
        if (!finite(view_matrix(in)))
            throw InputError("eye", "is too far from the origin to build the view matrix");
    }
    if (in.has_model) {
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                check_finite(in.model[c][r],
                             "model[" + std::to_string(r) + "][" + std::to_string(c) + "]");
        if (in.model[0][3] != 0 || in.model[1][3] != 0 || in.model[2][3] != 0 || in.model[3][3] != 1)
            throw InputError("model[3]", "must be [0, 0, 0, 1]: the model matrix is affine (got [" +
                                             given(in.model[0][3]) + ", " + given(in.model[1][3]) +
                                             ", " + given(in.model[2][3]) + ", " +
                                             given(in.model[3][3]) + "])");
    }
    if (in.has_viewport) {
        check_finite(in.viewport.x, "viewport[0]");
        check_finite(in.viewport.y, "viewport[1]");
        if (in.viewport.x <= 0 || in.viewport.y <= 0)
            throw InputError(in.viewport.x <= 0 ? "viewport[0]" : "viewport[1]",
                             "must be positive: the viewport is [width, height] in pixels (got " +
                                 given(in.viewport) + ")");
    }
    Result r;
    r.model = in.model;
    r.view = view_matrix(in);
    r.projection = projection_matrix(in);
    for (std::size_t k = 0; k < in.points.size(); ++k) {
        const std::string f = "points[" + std::to_string(k) + "]";
        check_finite(in.points[k], f);
        const dvec4 c = through(r, in.points[k]).clip;
        if (!finite(c)) throw InputError(f, "is too large to project (" + given(in.points[k]) + ")");
        // Just in front of the eye's plane (w > 0 but tiny) the divide overflows.
        if (c.w > 0 && !finite(dvec4(dvec3(c) / c.w, 1.0)))
            throw InputError(f, "lies too close to the eye's plane to divide (w = " + given(c.w) +
                                    "): its NDC coordinates overflow");
    }
    for (std::size_t k = 0; k < in.segments.size(); ++k) {
        for (int e = 0; e < 2; ++e) {
            const std::string f = "segments[" + std::to_string(k) + "][" + std::to_string(e) + "]";
            check_finite(in.segments[k][e], f);
            const dvec4 c = through(r, in.segments[k][e]).clip;
            if (!finite(c)) throw InputError(f, "is too large to project (" + given(in.segments[k][e]) + ")");
            // Cutting at the near plane interpolates w from the ends: an end 1e9 times farther
            // than the near plane would leave the cut's w (= near) to round-off.
            if (std::fabs(c.w) > 1e9 * in.near)
                throw InputError(f, "lies too far (depth " + given(std::fabs(c.w)) +
                                        ") for the near plane at " + given(in.near) +
                                        ": the cut would drown in round-off");
        }
        if (in.segments[k][0] == in.segments[k][1])
            throw InputError("segments[" + std::to_string(k) + "]",
                             "has both ends at " + given(in.segments[k][0]) + ": not a segment");
    }
}

Perspective::State Perspective::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

Perspective::State Perspective::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [advance] ------------------------------------------------------------------------------

void Perspective::advance(State& s) {
    s.last = s.phase;
    Result& r = s.r;
    const int n = static_cast<int>(s.in->points.size());
    const int m = static_cast<int>(s.in->segments.size());
    auto after_points = [&] { return m > 0 ? Phase::SegmentClip : Phase::Done; };
    switch (s.phase) {
        case Phase::Model:  // Model to world
            r.model = s.in->model;
            s.phase = Phase::View;
            return;
        case Phase::View: {  // The look-at frame
            const Frame fr = view_frame(*s.in);
            s.right = fr.right, s.up = fr.up, s.forward = fr.forward, s.eye = fr.eye;
            r.view = s.in->look_at ? view_from(fr, s.in->convention) : dmat4(1.0);
            s.phase = Phase::Projection;
            return;
        }
        case Phase::Projection:  // The perspective matrix
            r.projection = projection_matrix(*s.in);
            r.mvp = r.projection * r.view * r.model;
            r.world.reserve(n), r.eye_coords.reserve(n), r.clip.reserve(n), r.ndc.reserve(n);
            r.inside.reserve(n), r.device.reserve(n), r.segments.reserve(m);
            s.k = -1;
            s.phase = n > 0 ? Phase::PointView : after_points();
            return;
        case Phase::PointView: {  // Model → world → view
            ++s.k;
            const Through t = through(r, s.in->points[s.k]);
            r.world.push_back(t.world);
            r.eye_coords.push_back(t.view);
            s.phase = Phase::PointClip;
            return;
        }
        case Phase::PointClip: {  // View → clip
            const dvec4 c = r.projection * dvec4(r.eye_coords[s.k], 1.0);
            r.clip.push_back(c);
            r.inside.push_back(in_volume(c));
            s.phase = Phase::PointDivide;
            return;
        }
        case Phase::PointDivide: {  // The divide
            const dvec4 c = r.clip[s.k];
            if (c.w > 0)
                r.ndc.emplace_back(dvec3(c) / c.w);
            else
                r.ndc.emplace_back(std::nullopt);
            const bool device = s.in->has_viewport && c.w > 0;
            if (!device) r.device.emplace_back(std::nullopt);
            s.phase = device ? Phase::PointDevice : (s.k + 1 < n ? Phase::PointView : after_points());
            return;
        }
        case Phase::PointDevice: {  // NDC → viewport
            const dvec3 q = *r.ndc[s.k];
            r.device.emplace_back(dvec2((q.x + 1) * s.in->viewport.x / 2, (q.y + 1) * s.in->viewport.y / 2));
            s.phase = s.k + 1 < n ? Phase::PointView : after_points();
            return;
        }
        case Phase::SegmentClip: {  // Clip against the near plane, in clip space
            ++s.j;
            const auto& seg = s.in->segments[s.j];
            r.segments.push_back(clip_near(through(r, seg[0]).clip, through(r, seg[1]).clip));
            if (r.segments.back().status != Status::Rejected)
                s.phase = Phase::SegmentDivide;
            else
                s.phase = s.j + 1 < m ? Phase::SegmentClip : Phase::Done;
            return;
        }
        case Phase::SegmentDivide:  // The kept part's ends divided (done in clip_near)
            s.phase = s.j + 1 < m ? Phase::SegmentClip : Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string outside_planes(dvec4 c) {
    std::vector<std::string> v;
    if (c.x > c.w) v.push_back("x > w (right)");
    if (c.x < -c.w) v.push_back("x < −w (left)");
    if (c.y > c.w) v.push_back("y > w (above)");
    if (c.y < -c.w) v.push_back("y < −w (below)");
    if (c.z < -c.w) v.push_back("z < −w (nearer than the near plane)");
    if (c.z > c.w) v.push_back("z > w (beyond the far plane)");
    std::string t;
    for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + v[i];
    return t;
}

void narrate_model(const Perspective::State& s, StepInfo& info) {
    info.event = "model-matrix";
    info.line = kLineModel;
    info.narration = s.in->has_model
                         ? "The model matrix places the points in the world: M_model = " +
                               matrix_text(s.r.model) + "."
                         : "No model matrix given: M_model = I, the points are given in world "
                           "coordinates.";
    info.math = "M_{model} = " + matrix_tex(s.r.model);
}

void narrate_view(const Perspective::State& s, StepInfo& info) {
    const bool course = s.in->convention == Convention::Course;
    info.line = kLineView;
    if (!s.in->look_at) {
        info.event = "view-identity";
        info.narration = std::string("No eye, center or up given: V = I, world coordinates are "
                                     "view coordinates, with the eye at the origin looking down ") +
                         (course ? "+z (the course's convention)." : "−z (OpenGL's convention).");
        info.math = "V = I";
        return;
    }
    info.event = "view-frame";
    info.narration = "Eye " + num(s.in->eye) + " looking at " + num(s.in->center) +
                     ": view direction f̂ = " + num(s.forward, 4) + ", right r = f̂ × up/|…| = " +
                     num(s.right, 4) + ", up u = r × f̂ = " + num(s.up, 4) + ". V has rows r, u, " +
                     (course ? "f̂ (the course's view looks down +z)"
                             : "−f̂ (OpenGL's view looks down −z)") +
                     ", each with −row · eye as translation: V = " + matrix_text(s.r.view) + ".";
    info.math = "V = \\begin{bmatrix} r^T & -r \\cdot e \\\\ u^T & -u \\cdot e \\\\ " +
                std::string(course ? "\\hat f^T & -\\hat f \\cdot e" : "-\\hat f^T & \\hat f \\cdot e") +
                " \\\\ 0 & 1 \\end{bmatrix} = " + matrix_tex(s.r.view);
}

void narrate_frustum(const Perspective::State& s, StepInfo& info) {
    const bool course = s.in->convention == Convention::Course;
    const Perspective::Input& in = *s.in;
    const dmat4& p = s.r.projection;
    const std::string sx = course ? "−(r+l)/(r−l) = " : "(r+l)/(r−l) = ";
    const std::string sy = course ? "−(t+b)/(t−b) = " : "(t+b)/(t−b) = ";
    const bool off_axis = in.left != -in.right || in.bottom != -in.top;
    info.narration =
        "Frustum: near rectangle x ∈ [" + num(in.left) + ", " + num(in.right) + "], y ∈ [" +
        num(in.bottom) + ", " + num(in.top) + "] at depth n = " + num(in.near) + ", far " +
        num(in.far) + ". 2n/(r−l) = " + num(p[0][0], 4) + ", 2n/(t−b) = " + num(p[1][1], 4) +
        ", " + sx + num(p[2][0], 4) + ", " + sy + num(p[2][1], 4) +
        (off_axis ? " (off-axis: the window's centre (" + num((in.left + in.right) / 2) + ", " +
                        num((in.bottom + in.top) / 2) +
                        ") shifts x and y in proportion to depth, so the frustum leans)"
                  : " (symmetric: the same as the fov form)") +
        "; " + (course ? "(f+n)/(f−n) = " : "−(f+n)/(f−n) = ") + num(p[2][2], 4) +
        ", −2fn/(f−n) = " + num(p[3][2], 4) + ", and w = " + (course ? "z" : "−z") +
        ". P = " + matrix_text(p) + ": depth n goes to z_ndc = −1, depth f to +1.";
    const std::string sgn = course ? "-" : "";
    info.math = "P = \\begin{bmatrix} \\frac{2n}{r-l} & 0 & " + sgn +
                "\\frac{r+l}{r-l} & 0 \\\\ 0 & \\frac{2n}{t-b} & " + sgn +
                "\\frac{t+b}{t-b} & 0 \\\\ 0 & 0 & " +
                std::string(course ? "\\frac{f+n}{f-n}" : "-\\frac{f+n}{f-n}") +
                " & \\frac{-2fn}{f-n} \\\\ 0 & 0 & " + (course ? "1" : "-1") +
                " & 0 \\end{bmatrix} = " + matrix_tex(p);
}

void narrate_projection(const Perspective::State& s, StepInfo& info) {
    const bool course = s.in->convention == Convention::Course;
    const dmat4& p = s.r.projection;
    const double c = p[1][1];
    info.event = "projection-matrix";
    info.line = kLineProjection;
    if (s.in->has_frustum) {
        narrate_frustum(s, info);
        return;
    }
    info.narration = "fov_y = " + num(s.in->fov_y_deg) + "°: c = cot(" + num(s.in->fov_y_deg / 2) +
                     "°) = " + num(c, 4) + ", c/a = " + num(p[0][0], 4) + " for aspect " +
                     num(s.in->aspect) + "; near " + num(s.in->near) + ", far " + num(s.in->far) +
                     ": " + (course ? "(f+n)/(f−n) = " : "−(f+n)/(f−n) = ") + num(p[2][2], 4) +
                     ", −2fn/(f−n) = " + num(p[3][2], 4) + ", and w = " +
                     (course ? "z" : "−z") + ". P = " + matrix_text(p) +
                     ": depth n goes to z_ndc = −1, depth f to +1.";
    info.math = "P = \\begin{bmatrix} \\frac{\\cot(\\theta/2)}{a} & 0 & 0 & 0 \\\\ 0 & "
                "\\cot(\\theta/2) & 0 & 0 \\\\ 0 & 0 & " +
                std::string(course ? "\\frac{f+n}{f-n}" : "-\\frac{f+n}{f-n}") +
                " & \\frac{-2fn}{f-n} \\\\ 0 & 0 & " + (course ? "1" : "-1") +
                " & 0 \\end{bmatrix} = " + matrix_tex(p);
}

void narrate_point_view(const Perspective::State& s, StepInfo& info) {
    const int k = s.k;
    info.event = "point-to-view";
    info.line = kLinePointView;
    info.narration = point_name(k) + " = " + num(s.in->points[k]) + ": in the world " +
                     num(s.r.world[k], 4) + ", in view coordinates " + num(s.r.eye_coords[k], 4) +
                     " (depth " + num(zsign(s.in->convention) * s.r.eye_coords[k].z, 4) +
                     " along the view direction).";
    info.math = "p_{view} = V M_{model} p = " + tex(s.r.eye_coords[k], 4);
}

void narrate_point_clip(const Perspective::State& s, StepInfo& info) {
    const int k = s.k;
    const dvec4 c = s.r.clip[k];
    info.line = kLinePointClip;
    std::string text = point_name(k) + "_clip = P p_view = " + num4(c) + ": ";
    if (c.w <= 0) {
        info.event = "behind-eye";
        text += "w = " + num(c.w, 4) + " ≤ 0, the point is " +
                (c.w == 0 ? std::string("in the eye's own plane") : "behind the eye") + ".";
    } else if (s.r.inside[k]) {
        info.event = "inside-volume";
        text += "−w ≤ x, y, z ≤ w with w = " + num(c.w, 4) + ": inside the view volume.";
    } else {
        info.event = "outside-volume";
        text += "w = " + num(c.w, 4) + " > 0 but " + outside_planes(c) +
                ": outside the view volume (it would be clipped).";
    }
    info.narration = std::move(text);
    info.math = "P\\,p_{view} = " + column_tex(c);
}

void narrate_point_divide(const Perspective::State& s, StepInfo& info) {
    const int k = s.k;
    const dvec4 c = s.r.clip[k];
    info.line = kLinePointDivide;
    if (!s.r.ndc[k]) {
        info.event = "no-divide";
        info.narration =
            c.w == 0 ? point_name(k) + ": w = 0, dividing by it is impossible — the point has no image."
                     : point_name(k) + ": w = " + num(c.w, 4) + " < 0, so no divide: (x/w, y/w) = " +
                           num(dvec2(c.x / c.w, c.y / c.w), 4) +
                           " would put the point behind the eye on the screen, mirrored through "
                           "the centre.";
        info.math = "w = " + tex(c.w, 4) + " \\le 0";
        return;
    }
    const dvec3 q = *s.r.ndc[k];
    info.event = "divide";
    info.narration = point_name(k) + "_ndc = (x/w, y/w, z/w) = (" + num(c.x, 4) + "/" + num(c.w, 4) +
                     ", " + num(c.y, 4) + "/" + num(c.w, 4) + ", " + num(c.z, 4) + "/" +
                     num(c.w, 4) + ") = " + num(q, 4) +
                     (s.r.inside[k] ? ", inside the cube [−1, 1]³." : ", outside the cube [−1, 1]³.");
    info.math = "p_{ndc} = \\left(\\frac{x}{w}, \\frac{y}{w}, \\frac{z}{w}\\right) = " + tex(q, 4);
}

void narrate_point_device(const Perspective::State& s, StepInfo& info) {
    const int k = s.k;
    const dvec3 q = *s.r.ndc[k];
    const dvec2 d = *s.r.device[k];
    info.event = "to-viewport";
    info.line = kLinePointDevice;
    info.narration = point_name(k) + "_device = ((" + num(q.x, 4) + " + 1)·" + num(s.in->viewport.x) +
                     "/2, (" + num(q.y, 4) + " + 1)·" + num(s.in->viewport.y) + "/2) = " +
                     num(d, 4) + " px.";
    info.math = "p_{device} = " + tex(d, 4);
}

void narrate_segment_clip(const Perspective::State& s, StepInfo& info) {
    const int k = s.j;
    const Perspective::Segment& g = s.r.segments[k];
    const double da = near_distance(g.clip[0]), db = near_distance(g.clip[1]);
    info.line = kLineSegmentClip;
    std::string text = segment_name(k) + ": A → " + num4(g.clip[0]) + " with d_A = z + w = " +
                       num(da, 4) + ", B → " + num4(g.clip[1]) + " with d_B = " + num(db, 4) + ". ";
    switch (g.status) {
        case Status::Inside:
            info.event = "segment-kept";
            text += "Both d ≥ 0: the whole segment lies beyond the near plane, kept as it is.";
            break;
        case Status::Rejected:
            info.event = "segment-rejected";
            text += "Both d < 0: the segment lies entirely nearer than the near plane (or behind "
                    "the eye), discarded before any divide.";
            break;
        case Status::Clipped: {
            info.event = "segment-clipped";
            const double t = da < 0 ? g.t0 : g.t1;
            const dvec4 cut = da < 0 ? g.kept[0] : g.kept[1];
            text += "d changes sign: cut at t = d_A/(d_A − d_B) = " + num(t, 4) + ", the point " +
                    num4(cut) + " on the near plane (z = −w); keep " +
                    (da < 0 ? "the part towards B" : "the part towards A") + ", t ∈ [" +
                    num(g.t0, 4) + ", " + num(g.t1, 4) + "].";
            break;
        }
    }
    info.narration = std::move(text);
    info.math = "d_A = " + tex(da, 4) + ",\\ d_B = " + tex(db, 4) +
                (g.status == Status::Clipped
                     ? ",\\ t = \\frac{d_A}{d_A - d_B} = " + tex(da < 0 ? g.t0 : g.t1, 4)
                     : std::string());
}

void narrate_segment_divide(const Perspective::State& s, StepInfo& info) {
    const int k = s.j;
    const Perspective::Segment& g = s.r.segments[k];
    info.event = "segment-divide";
    info.line = kLineSegmentDivide;
    std::string text = segment_name(k) + ": the kept part runs from " + num(g.ndc[0], 4) + " to " +
                       num(g.ndc[1], 4) + " in NDC.";
    if (g.status == Status::Clipped) {
        const int gone = near_distance(g.clip[0]) < 0 ? 0 : 1;
        const dvec4 c = g.clip[gone];
        const std::string end = gone == 0 ? "A" : "B";
        if (c.w > 0)
            text += " Dividing the dropped end " + end + " instead would give z_ndc = " +
                    num(c.z / c.w, 4) + " < −1: nearer than the near plane.";
        else if (c.w < 0)
            text += " Dividing the dropped end " + end + " (w = " + num(c.w, 4) +
                    ") instead would give " + num(dvec2(c.x / c.w, c.y / c.w), 4) +
                    ", on the wrong side of the screen: that is why the near plane is clipped "
                    "before the divide.";
        else
            text += " The dropped end " + end + " has w = 0: dividing by it is impossible.";
    }
    info.narration = std::move(text);
    info.math = "\\left(\\frac{x}{w}, \\frac{y}{w}, \\frac{z}{w}\\right): " + tex(g.ndc[0], 4) +
                " \\to " + tex(g.ndc[1], 4);
}

void fill_vars(const Perspective::State& s, StepInfo& info) {
    if (s.in->has_frustum)
        info.vars = {{"left", s.in->left},     {"right", s.in->right}, {"bottom", s.in->bottom},
                     {"top", s.in->top},       {"near", s.in->near},   {"far", s.in->far},
                     {"M_model", rows(s.r.model)}};
    else
        info.vars = {{"fov_y_deg", s.in->fov_y_deg},
                     {"aspect", s.in->aspect},
                     {"near", s.in->near},
                     {"far", s.in->far},
                     {"M_model", rows(s.r.model)}};
    if (s.last >= Phase::View) info.vars.push_back({"V", rows(s.r.view)});
    if (s.last >= Phase::Projection) info.vars.push_back({"P", rows(s.r.projection)});
    const int k = s.k;
    if (s.last >= Phase::PointView && s.last <= Phase::PointDevice) {
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"p", vec(s.in->points[k])});
        info.vars.push_back({"p_world", vec(s.r.world[k])});
        info.vars.push_back({"p_view", vec(s.r.eye_coords[k])});
        if (s.last >= Phase::PointClip) {
            info.vars.push_back({"p_clip", vec4(s.r.clip[k])});
            info.vars.push_back({"inside", static_cast<bool>(s.r.inside[k])});
        }
        if (s.last >= Phase::PointDivide && s.r.ndc[k]) info.vars.push_back({"p_ndc", vec(*s.r.ndc[k])});
        if (s.last == Phase::PointDevice) info.vars.push_back({"p_device", vec(*s.r.device[k])});
    }
    if (s.last == Phase::SegmentClip || s.last == Phase::SegmentDivide) {
        const int k = s.j;
        const Perspective::Segment& g = s.r.segments[k];
        info.vars.push_back({"k", static_cast<long long>(k)});
        info.vars.push_back({"A_clip", vec4(g.clip[0])});
        info.vars.push_back({"B_clip", vec4(g.clip[1])});
        info.vars.push_back({"d_A", near_distance(g.clip[0])});
        info.vars.push_back({"d_B", near_distance(g.clip[1])});
        if (g.status != Status::Rejected) {
            info.vars.push_back({"t0", g.t0});
            info.vars.push_back({"t1", g.t1});
        }
        if (s.last == Phase::SegmentDivide) {
            info.vars.push_back({"A_ndc", vec(g.ndc[0])});
            info.vars.push_back({"B_ndc", vec(g.ndc[1])});
        }
    }
}

}  // namespace

void Perspective::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::Model: narrate_model(s, info); break;
        case Phase::View: narrate_view(s, info); break;
        case Phase::Projection: narrate_projection(s, info); break;
        case Phase::PointView: narrate_point_view(s, info); break;
        case Phase::PointClip: narrate_point_clip(s, info); break;
        case Phase::PointDivide: narrate_point_divide(s, info); break;
        case Phase::PointDevice: narrate_point_device(s, info); break;
        case Phase::SegmentClip: narrate_segment_clip(s, info); break;
        case Phase::SegmentDivide:
        case Phase::Done: narrate_segment_divide(s, info); break;
    }
    fill_vars(s, info);
}

void Perspective::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

// ---- [project] ------------------------------------------------------------------------------

[[gnu::flatten]] Perspective::Result Perspective::project(const Input& in) {
    Result r;
    r.model = in.model;
    r.view = view_matrix(in);
    r.projection = projection_matrix(in);
    r.mvp = r.projection * r.view * r.model;
    const std::size_t n = in.points.size();
    r.world.reserve(n), r.eye_coords.reserve(n), r.clip.reserve(n), r.ndc.reserve(n);
    r.inside.reserve(n), r.device.reserve(n), r.segments.reserve(in.segments.size());
    for (const dvec3 p : in.points) {
        const Through t = through(r, p);
        r.world.push_back(t.world);
        r.eye_coords.push_back(t.view);
        r.clip.push_back(t.clip);
        r.inside.push_back(in_volume(t.clip));
        if (t.clip.w > 0) {
            const dvec3 q = dvec3(t.clip) / t.clip.w;
            r.ndc.emplace_back(q);
            if (in.has_viewport)
                r.device.emplace_back(dvec2((q.x + 1) * in.viewport.x / 2, (q.y + 1) * in.viewport.y / 2));
            else
                r.device.emplace_back(std::nullopt);
        } else {
            r.ndc.emplace_back(std::nullopt);
            r.device.emplace_back(std::nullopt);
        }
    }
    for (const auto& seg : in.segments)
        r.segments.push_back(clip_near(through(r, seg[0]).clip, through(r, seg[1]).clip));
    return r;
}

}  // namespace cg
