// Sections: [helpers] [spec] [validate] [the model's terms] [advance] [narrate]; the picture is
// in phong_lighting_draw.cpp.
#include "rays/phong_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/format.hpp"
#include "rays/quadric.hpp"  // unit()

namespace cg {

namespace {

using glm::dvec3;
using Color = PhongLighting::Color;
using Phase = PhongLighting::Phase;
using Model = PhongLighting::Model;

// ---- [helpers] ------------------------------------------------------------------------------

enum Line {
    kLineView = 1,
    kLineAmbient,
    kLineLight,
    kLineDiffuse,
    kLineSpecular,
    kLineBlinn,
    kLineTotal,
};

double dot(dvec3 a, dvec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

dvec3 unit_of(dvec3 v) {
    return unit(v);
}

void check_finite3(dvec3 v, const std::string& field) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            throw InputError(field + "[" + std::to_string(i) + "]",
                             "must be a finite number (got " + given(v[i]) + ")");
}

// A colour or coefficient: finite and ≥ 0 on every channel. A scalar names no channel.
void check_color(const Color& c, bool rgb, const std::string& field, const char* what) {
    for (int i = 0; i < 3; ++i) {
        const std::string f = rgb ? field + "[" + std::to_string(i) + "]" : field;
        if (!std::isfinite(c[i]))
            throw InputError(f, "must be a finite number (got " + given(c[i]) + ")");
        if (c[i] < 0)
            throw InputError(
                f, std::string("must not be negative: ") + what + " (got " + given(c[i]) + ")");
        if (c[i] > 1e100) throw InputError(f, "is too large (got " + given(c[i]) + ")");
    }
}

// "0.5" for a scalar (all channels equal and the input had no colours), "(0.5, 0.2, 0)".
std::string ctext(const Color& c, bool rgb, int digits = 6) {
    return rgb ? num(c, digits) : num(c.x, digits);
}
std::string ctex(const Color& c, bool rgb) {
    return rgb ? tex(c) : tex(c.x);
}

}  // namespace

// ---- [spec] ---------------------------------------------------------------------------------

const Spec& PhongLighting::spec() {
    static const Spec spec{
        "phong-lighting",
        "Phong and Blinn-Phong lighting at a point",
        "Lighting",
        {
            "n ← n/|n|;  v ← (E − P)/|E − P|",
            "I ← k_a I_a                                   ▷ ambient",
            "for each light i:  l ← (L − P)/|L − P| or −dir;  att ← 1/(c1 + c2 r + c3 r²) or 1",
            "    I += att I_i k_d max(l·n, 0)               ▷ Lambert",
            "    Phong:  if l·n > 0:  I += att I_i k_s max(r·v, 0)^p,  r ← −l + 2(l·n)n",
            "    Blinn:  if l·n > 0:  I += att I_i k_s max(h·n, 0)^p,  h ← (v + l)/|v + l|",
            "return I = ambient + Σ diffuse + Σ specular",
        },
        {
            {"view", "the unit normal n and the unit vector v toward the eye"},
            {"ambient", "the ambient term k_a I_a, the same everywhere"},
            {"point-light", "a point light: l toward it, its distance and attenuation"},
            {"directional-light", "a directional light: l against its direction, no attenuation"},
            {"diffuse", "Lambert's term k_d (l·n), scaled by the light's intensity"},
            {"light-behind", "l·n ≤ 0: the light is behind the surface and adds nothing"},
            {"phong-specular", "Phong's highlight k_s (r·v)^p with r the mirrored light"},
            {"blinn-specular", "Blinn-Phong's highlight k_s (h·n)^p with h the halfway vector"},
            {"no-specular", "the light is behind the surface: no highlight"},
            {"total", "the three terms summed"},
        },
        {},  // no sliders
        {
            .predict = {
                {"diffuse", {"n_dot_l", "diffuse"}},
                {"phong-specular", {"r_dot_v", "specular"}},
                {"blinn-specular", {"n_dot_h", "specular"}},
                {"total", {"intensity"}},
            },
            .mistakes = {
                {"point-light", "l", "negate", "took l from the light to the point"},
                {"view", "v", "negate", "took v from the eye to the point"},
                {"blinn-specular", "", "event:phong-specular",
                 "used r · v where Blinn-Phong needs n · h"},
            },
            .variants = {
                {"phong", "/model", "\"phong\""},
                {"blinn-phong", "/model", "\"blinn-phong\""},
            },
        },
    };
    return spec;
}

// ---- [validate] -----------------------------------------------------------------------------

void PhongLighting::validate(const Input& in) {
    check_finite3(in.point, "point");
    check_finite3(in.normal, "normal");
    check_finite3(in.eye, "eye");
    if (in.normal == dvec3(0.0))
        throw InputError("normal", "must not be the zero vector: the surface needs a normal");
    if (in.eye == in.point)
        throw InputError("eye",
                         "must differ from point: the view direction v = (E − P)/|E − P| "
                         "is undefined when the eye is at the point");
    if (!std::isfinite(glm::length(in.normal) + 1))
        throw InputError("normal", "is too large to normalise (got " + given(in.normal) + ")");
    if (!std::isfinite(glm::length(in.eye - in.point))) {
        // Name the field that is out of range: the one with the larger coordinate.
        const auto big = [](const dvec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); };
        throw InputError(big(in.point) > big(in.eye) ? "point" : "eye",
                         "is too far from the " + std::string(big(in.point) > big(in.eye) ? "eye" : "point") +
                             " for double precision");
    }
    validate_lighting(in);
    for (std::size_t i = 0; i < in.lights.size(); ++i) {
        const Light& L = in.lights[i];
        if (L.directional) continue;
        const std::string f = "lights[" + std::to_string(i) + "]";
        if (L.position == in.point)
            throw InputError(f + ".position",
                             "must differ from point: the light's direction l "
                             "is undefined when it sits on the surface point");
        const double r = glm::length(L.position - in.point);
        const double den = L.attenuation.x + L.attenuation.y * r + L.attenuation.z * r * r;
        if (!std::isfinite(r) || !std::isfinite(den) || !(den > 0) || !std::isfinite(1 / den))
            throw InputError(f + ".position",
                             "is too far from or too close to the point for "
                             "double precision (distance " +
                                 given(r) + ")");
    }
}

void PhongLighting::validate_lighting(const Input& in) {
    check_color(in.ambient, in.rgb, "ambient", "an intensity");
    check_color(in.material.ka, in.rgb, "material.ka", "a reflection coefficient");
    check_color(in.material.kd, in.rgb, "material.kd", "a reflection coefficient");
    check_color(in.material.ks, in.rgb, "material.ks", "a reflection coefficient");
    const double p = in.material.shininess;
    if (!std::isfinite(p))
        throw InputError("material.shininess", "must be a finite number (got " + given(p) + ")");
    if (p < 0)
        throw InputError("material.shininess",
                         "must not be negative (got " + given(p) +
                             "): (r·v)^p with p < 0 would make the highlight brightest away from "
                             "the mirror direction and infinite at r·v = 0");
    if (p > 1e6) throw InputError("material.shininess", "is too large (got " + given(p) + ")");
    for (std::size_t i = 0; i < in.lights.size(); ++i) {
        const Light& L = in.lights[i];
        const std::string f = "lights[" + std::to_string(i) + "]";
        check_color(L.intensity, in.rgb, f + ".intensity", "an intensity");
        if (L.directional) {
            check_finite3(L.direction, f + ".direction");
            if (L.direction == dvec3(0.0))
                throw InputError(f + ".direction", "must not be the zero vector");
            if (L.attenuation != dvec3(1, 0, 0))
                throw InputError(f + ".attenuation",
                                 "is only for point lights: a directional light is not "
                                 "attenuated (its energy does not spread out)");
            continue;
        }
        check_finite3(L.position, f + ".position");
        for (int k = 0; k < 3; ++k) {
            const std::string af = f + ".attenuation[" + std::to_string(k) + "]";
            if (!std::isfinite(L.attenuation[k]))
                throw InputError(af, "must be a finite number (got " + given(L.attenuation[k]) + ")");
            if (L.attenuation[k] < 0)
                throw InputError(af, "must not be negative (got " + given(L.attenuation[k]) + ")");
        }
        if (L.attenuation == dvec3(0.0))
            throw InputError(f + ".attenuation",
                             "must not be all zero: 1/(c1 + c2 r + c3 r²) would divide by 0");
    }
}

PhongLighting::State PhongLighting::start(const Input& in) {
    validate(in);
    return begin(Shared<Input>(in));
}

PhongLighting::State PhongLighting::begin(Shared<Input> in) {
    State s;
    s.in = std::move(in);
    return s;
}

// ---- [the model's terms] --------------------------------------------------------------------

namespace {

// l, distance and attenuation of light L at P.
void light_direction(const PhongLighting::Light& L, dvec3 P, PhongLighting::LightTerms& t) {
    if (L.directional) {
        t.l = -unit_of(L.direction);
        t.distance = 0;
        t.attenuation = 1;
    } else {
        const dvec3 to = L.position - P;
        t.distance = std::sqrt(dot(to, to));
        t.l = unit_of(to);
        const dvec3 c = L.attenuation;
        t.attenuation = 1 / (c.x + c.y * t.distance + c.z * t.distance * t.distance);
    }
}

void diffuse_term(const PhongLighting::Input& in, dvec3 n, PhongLighting::LightTerms& t,
                  const PhongLighting::Light& L) {
    t.n_dot_l = dot(n, t.l);
    t.diffuse = t.attenuation * std::max(t.n_dot_l, 0.0) * (in.material.kd * L.intensity);
}

// Both reflection vectors are computed (the result reports both); the model picks one.
void specular_term(const PhongLighting::Input& in, dvec3 n, dvec3 v, PhongLighting::LightTerms& t,
                   const PhongLighting::Light& L) {
    t.r = 2 * t.n_dot_l * n - t.l;
    t.r_dot_v = dot(t.r, v);
    t.h = unit_of(v + t.l);
    t.n_dot_h = dot(n, t.h);
    if (!(t.n_dot_l > 0)) {
        t.specular = Color(0.0);
        return;
    }
    const double cosine = in.model == Model::Phong ? t.r_dot_v : t.n_dot_h;
    const double s = std::pow(std::max(cosine, 0.0), in.material.shininess);
    t.specular = t.attenuation * s * (in.material.ks * L.intensity);
}

}  // namespace

// ---- [advance] ------------------------------------------------------------------------------

void PhongLighting::advance(State& s) {
    s.last = s.phase;
    // The light count is read only where a phase chooses what follows (a size is a division).
    const auto n_lights = [&s] { return static_cast<int>(s.in->lights.size()); };
    Result& o = s.out;
    switch (s.phase) {
        case Phase::View:  // The unit normal and the view vector
            o.rgb = s.in->rgb;
            o.n = unit_of(s.in->normal);
            o.v = unit_of(s.in->eye - s.in->point);
            o.lights.reserve(s.in->lights.size());
            s.phase = Phase::Ambient;
            return;
        case Phase::Ambient:  // The ambient term
            o.ambient = s.in->material.ka * s.in->ambient;
            s.phase = n_lights() > 0 ? Phase::LightDir : Phase::Total;
            return;
        case Phase::LightDir:  // The next light: its direction and attenuation
            ++s.k;
            o.lights.emplace_back();
            light_direction(s.in->lights[s.k], s.in->point, o.lights.back());
            s.phase = Phase::Diffuse;
            return;
        case Phase::Diffuse:  // Lambert's term
            diffuse_term(*s.in, o.n, o.lights.back(), s.in->lights[s.k]);
            o.diffuse += o.lights.back().diffuse;
            s.phase = Phase::Specular;
            return;
        case Phase::Specular:  // The highlight
            specular_term(*s.in, o.n, o.v, o.lights.back(), s.in->lights[s.k]);
            o.specular += o.lights.back().specular;
            s.phase = s.k + 1 < n_lights() ? Phase::LightDir : Phase::Total;
            return;
        case Phase::Total:  // The sum
            o.intensity = o.ambient + o.diffuse + o.specular;
            s.phase = Phase::Done;
            return;
        case Phase::Done:
            return;
    }
}

void PhongLighting::step(State& s, StepInfo* info) {
    if (s.phase == Phase::Done) return;
    advance(s);
    if (info) narrate(s, *info);
}

[[gnu::flatten]] PhongLighting::Result PhongLighting::shade(const Input& in) {
    return shade(in, in.point, in.normal);
}

[[gnu::flatten]] PhongLighting::Result PhongLighting::shade(const Input& in, dvec3 point,
                                                            dvec3 normal) {
    Result o;
    o.rgb = in.rgb;
    o.n = unit_of(normal);
    o.v = unit_of(in.eye - point);
    o.ambient = in.material.ka * in.ambient;
    o.lights.resize(in.lights.size());
    for (std::size_t i = 0; i < in.lights.size(); ++i) {
        LightTerms& t = o.lights[i];
        light_direction(in.lights[i], point, t);
        diffuse_term(in, o.n, t, in.lights[i]);
        o.diffuse += t.diffuse;
        specular_term(in, o.n, o.v, t, in.lights[i]);
        o.specular += t.specular;
    }
    o.intensity = o.ambient + o.diffuse + o.specular;
    return o;
}

// ---- [narrate] ------------------------------------------------------------------------------

namespace {

std::string light_name(int k) {
    return "light " + std::to_string(k);
}

void narrate_view(const PhongLighting::State& s, StepInfo& info) {
    const auto& o = s.out;
    info.event = "view";
    info.line = kLineView;
    const double nv = dot(o.n, o.v);
    info.narration =
        "n = " + num(s.in->normal) + "/|n| = " + num(o.n) +
        "; v = (E − P)/|E − P| = " + num(s.in->eye - s.in->point) + "/" +
        num(glm::length(s.in->eye - s.in->point)) + " = " + num(o.v) +
        (nv < 0 ? ". n·v = " + num(nv) + " < 0: the eye looks at the back of the surface." : ".");
    info.math = "n = \\frac{" + tex(s.in->normal) + "}{" + tex(glm::length(s.in->normal)) +
                "} = " + tex(o.n) + ",\\quad v = \\frac{E - P}{|E - P|} = " + tex(o.v);
}

void narrate_ambient(const PhongLighting::State& s, StepInfo& info) {
    const bool rgb = s.in->rgb;
    info.event = "ambient";
    info.line = kLineAmbient;
    info.narration = "Ambient: k_a I_a = " + ctext(s.in->material.ka, rgb) + " · " +
                     ctext(s.in->ambient, rgb) + " = " + ctext(s.out.ambient, rgb) +
                     ", a stand-in for light bounced around the scene, the same at every point.";
    info.math = "k_a I_a = " + ctex(s.in->material.ka, rgb) + " \\cdot " + ctex(s.in->ambient, rgb) +
                " = " + ctex(s.out.ambient, rgb);
}

void narrate_light(const PhongLighting::State& s, StepInfo& info) {
    const PhongLighting::Light& L = s.in->lights[s.k];
    const PhongLighting::LightTerms& t = s.out.lights.back();
    info.line = kLineLight;
    if (L.directional) {
        info.event = "directional-light";
        info.narration = light_name(s.k) + " is directional, travelling along " + num(L.direction) +
                         ": l = −dir/|dir| = " + num(t.l) +
                         ", no attenuation (its energy does not spread out).";
        info.math = "l = -\\frac{" + tex(L.direction) + "}{|\\cdot|} = " + tex(t.l) +
                    ",\\quad \\text{att} = 1";
        return;
    }
    const dvec3 c = L.attenuation;
    info.event = "point-light";
    info.narration = light_name(s.k) + " at " + num(L.position) +
                     ": l = (L − P)/|L − P| = " + num(t.l) + ", distance r = " + num(t.distance) +
                     ", attenuation 1/(c1 + c2·r + c3·r²) = 1/(" + num(c.x) + " + " + num(c.y) +
                     "·" + num(t.distance) + " + " + num(c.z) + "·" + num(t.distance) +
                     "²) = " + num(t.attenuation) + ".";
    info.math = "l = \\frac{L - P}{|L - P|} = " + tex(t.l) + ",\\quad r = " + tex(t.distance) +
                ",\\quad \\text{att} = \\frac{1}{" + tex(c.x) + " + " + tex(c.y) + " \\cdot " +
                tex(t.distance) + " + " + tex(c.z) + " \\cdot " + tex(t.distance) +
                "^2} = " + tex(t.attenuation);
}

void narrate_diffuse(const PhongLighting::State& s, StepInfo& info) {
    const PhongLighting::Light& L = s.in->lights[s.k];
    const PhongLighting::LightTerms& t = s.out.lights.back();
    const bool rgb = s.in->rgb;
    info.line = kLineDiffuse;
    if (!(t.n_dot_l > 0)) {
        info.event = "light-behind";
        info.narration = "l·n = " + num(t.n_dot_l) + " ≤ 0: " + light_name(s.k) +
                         " is behind the surface (or grazing it) and lights nothing here.";
        info.math =
            "l \\cdot n = " + tex(t.n_dot_l) + " \\le 0 \\Rightarrow k_d \\max(l \\cdot n, 0) = 0";
        return;
    }
    info.event = "diffuse";
    info.narration = "Lambert: att · I · k_d · (l·n) = " + num(t.attenuation) + " · " +
                     ctext(L.intensity, rgb) + " · " + ctext(s.in->material.kd, rgb) + " · " +
                     num(t.n_dot_l) + " = " + ctext(t.diffuse, rgb) +
                     " (l·n is the cosine of the light's angle from the normal).";
    info.math = "\\text{att}\\, I\\, k_d\\, (l \\cdot n) = " + tex(t.attenuation) + " \\cdot " +
                ctex(L.intensity, rgb) + " \\cdot " + ctex(s.in->material.kd, rgb) + " \\cdot " +
                tex(t.n_dot_l) + " = " + ctex(t.diffuse, rgb);
}

void narrate_specular(const PhongLighting::State& s, StepInfo& info) {
    const PhongLighting::Light& L = s.in->lights[s.k];
    const PhongLighting::LightTerms& t = s.out.lights.back();
    const bool rgb = s.in->rgb;
    const double p = s.in->material.shininess;
    info.line = s.in->model == Model::Phong ? kLineSpecular : kLineBlinn;
    if (!(t.n_dot_l > 0)) {
        info.event = "no-specular";
        info.narration = "The light is behind the surface (l·n = " + num(t.n_dot_l) +
                         "), so there is no highlight from " + light_name(s.k) + " either.";
        info.math = "l \\cdot n \\le 0 \\Rightarrow \\text{specular} = 0";
        return;
    }
    const std::string tail = " · " + num(t.attenuation) + " · " + ctext(L.intensity, rgb) + " · " +
                             ctext(s.in->material.ks, rgb) + " = " + ctext(t.specular, rgb) + ".";
    if (s.in->model == Model::Phong) {
        info.event = "phong-specular";
        info.narration = "Phong: r = −l + 2(l·n)n = " + num(t.r) + ", r·v = " + num(t.r_dot_v) +
                         (t.r_dot_v < 0 ? " (clamped to 0)" : "") +
                         ", (r·v)^p = " + num(std::max(t.r_dot_v, 0.0)) + "^" + num(p) + " = " +
                         num(std::pow(std::max(t.r_dot_v, 0.0), p)) + "; specular = that" + tail;
        info.math = "r = -l + 2(l \\cdot n)n = " + tex(t.r) +
                    ",\\quad (r \\cdot v)^p = " + tex(std::max(t.r_dot_v, 0.0)) + "^{" + tex(p) +
                    "} = " + tex(std::pow(std::max(t.r_dot_v, 0.0), p)) +
                    ",\\quad \\text{att}\\, I\\, k_s\\, (r \\cdot v)^p = " + ctex(t.specular, rgb);
    } else {
        info.event = "blinn-specular";
        info.line = kLineBlinn;
        info.narration = "Blinn-Phong: h = (v + l)/|v + l| = " + num(t.h) +
                         ", h·n = " + num(t.n_dot_h) + (t.n_dot_h < 0 ? " (clamped to 0)" : "") +
                         ", (h·n)^p = " + num(std::max(t.n_dot_h, 0.0)) + "^" + num(p) + " = " +
                         num(std::pow(std::max(t.n_dot_h, 0.0), p)) + "; specular = that" + tail;
        info.math = "h = \\frac{v + l}{|v + l|} = " + tex(t.h) +
                    ",\\quad (h \\cdot n)^p = " + tex(std::max(t.n_dot_h, 0.0)) + "^{" + tex(p) +
                    "} = " + tex(std::pow(std::max(t.n_dot_h, 0.0), p)) +
                    ",\\quad \\text{att}\\, I\\, k_s\\, (h \\cdot n)^p = " + ctex(t.specular, rgb);
    }
}

void narrate_total(const PhongLighting::State& s, StepInfo& info) {
    const auto& o = s.out;
    const bool rgb = s.in->rgb;
    info.event = "total";
    info.line = kLineTotal;
    info.narration = "I = ambient + diffuse + specular = " + ctext(o.ambient, rgb) + " + " +
                     ctext(o.diffuse, rgb) + " + " + ctext(o.specular, rgb) + " = " +
                     ctext(o.intensity, rgb) +
                     (std::max({o.intensity.x, o.intensity.y, o.intensity.z}) > 1
                          ? " (above 1: a display clamps it)."
                          : ".");
    info.math = "I = " + ctex(o.ambient, rgb) + " + " + ctex(o.diffuse, rgb) + " + " +
                ctex(o.specular, rgb) + " = " + ctex(o.intensity, rgb);
}

Value color_value(const Color& c, bool rgb) {
    if (rgb) return vec(c);
    return c.x;
}

void fill_vars(const PhongLighting::State& s, StepInfo& info) {
    const auto& o = s.out;
    const bool rgb = s.in->rgb;
    info.vars = {{"n", vec(o.n)}, {"v", vec(o.v)}};
    if (s.last >= Phase::Ambient) info.vars.push_back({"ambient", color_value(o.ambient, rgb)});
    if (s.k >= 0) {
        const auto& t = o.lights.back();
        info.vars.push_back({"light", static_cast<long long>(s.k)});
        info.vars.push_back({"l", vec(t.l)});
        info.vars.push_back({"attenuation", t.attenuation});
        if (s.last != Phase::LightDir) info.vars.push_back({"n_dot_l", t.n_dot_l});
        if (s.last == Phase::Specular || s.last == Phase::Total) {
            if (s.in->model == Model::Phong) {
                info.vars.push_back({"r", vec(t.r)});
                info.vars.push_back({"r_dot_v", t.r_dot_v});
            } else {
                info.vars.push_back({"h", vec(t.h)});
                info.vars.push_back({"n_dot_h", t.n_dot_h});
            }
        }
        info.vars.push_back({"diffuse", color_value(o.diffuse, rgb)});
        info.vars.push_back({"specular", color_value(o.specular, rgb)});
    }
    if (s.last == Phase::Total) info.vars.push_back({"intensity", color_value(o.intensity, rgb)});
}

}  // namespace

void PhongLighting::narrate(const State& s, StepInfo& info) {
    info.math.clear();
    switch (s.last) {
        case Phase::View:
            narrate_view(s, info);
            break;
        case Phase::Ambient:
            narrate_ambient(s, info);
            break;
        case Phase::LightDir:
            narrate_light(s, info);
            break;
        case Phase::Diffuse:
            narrate_diffuse(s, info);
            break;
        case Phase::Specular:
            narrate_specular(s, info);
            break;
        case Phase::Total:
        case Phase::Done:
            narrate_total(s, info);
            break;
    }
    fill_vars(s, info);
}

}  // namespace cg
