// A ray tracer's world: camera, lights, materials and objects, and the plain recursive tracer
// over it (Whitted's: shadows, mirror reflection and refraction, to a depth limit).
//
// The course's setting: an eye E and a virtual screen of pixels in front of it; the ray through
// pixel (i, j) is E + t (P − E), t > 0, P the pixel's centre on the screen. At the nearest hit
// the point is shaded with the Phong or Blinn-Phong model (rays/phong_lighting.hpp's formulas),
// counting a light only when a shadow ray from the point to the light reaches it unblocked;
// then secondary rays are cast in the mirror direction and, through transparent material, in
// the refracted direction, and their colours are added, weighted by the material's kr and kt:
//
//   colour(ray) = k_a I_a + Σ_visible lights  att_i I_i (k_d (l_i·n) + k_s S_i)
//               + k_r colour(reflected ray) + k_t colour(refracted ray)      (depth < limit)
//
// A ray that hits nothing returns the background colour. Ray casting is the same tracer with
// no secondary rays at all: depth limit 0 and no shadow rays.
//
// Conventions. World space is right-handed. The camera looks from `eye` toward `center`;
// w = (center − eye)/|center − eye| is the view direction, u = w × up (right), v = u × w (up):
// the screen is the rectangle at distance 1 along w, 2 tan(fov_y/2) tall and `aspect` times
// as wide. Pixel (i, j) is column i from the left and row j from the BOTTOM (y up, the
// project's pixel convention), its centre at (i + ½, j + ½) in pixel units; an image file is
// written top row first. The primary ray's direction is d = P − E (so t = 1 on the screen);
// secondary rays have unit directions. Normals: a quadric's along ∇F (rays/quadric.hpp), a
// plane's as given, a triangle's (p1 − p0) × (p2 − p0) (its vertices counter-clockwise seen
// from the front) or, when it has vertex normals n0, n1, n2 (a smooth mesh), the unit
// (1 − β − γ) n0 + β n1 + γ n2 at the hit's barycentric coordinates β, γ (the flat one where
// they cancel; bent along the ray onto the flat normal's side of the ray where, near the
// outline, it faces the other way); for shading the normal is turned to face the incoming ray, and a ray that
// met that normal head-on (d·n ≤ 0) is entering the solid. Refraction (Snell's law,
// η₁ sin θ₁ = η₂ sin θ₂) bends a ray entering a material of index `ior` from the outside
// (index 1) by η = 1/ior, and a leaving one by η = ior; when η sin θ₁ > 1 there is no
// refracted ray (total internal reflection) and the transmitted share kt goes to the mirror
// ray instead. Colours are linear r, g, b; a pixel's 8-bit value is round(255 clamp(c, 0, 1)).
// Secondary rays start a small distance off the surface along the normal (on the side they
// travel into), so they do not hit the surface they leave. Shadow rays treat every object as
// opaque (a glass ball casts a full shadow), as the course's tracer does. A point light's
// attenuation 1/(c1 + c2 r + c3 r²) is capped at 10⁶, so a light touching a surface stays finite.
//
// Distribution ray tracing (Cook's): a pixel's colour is the filtered average of
// settings.samples_per_pixel primary rays, placed in the pixel by a sample pattern
// (sampling/patterns.hpp; one sample is the pixel's centre, whatever the pattern), each through a
// point of the lens (camera.aperture: a thin lens of that radius focused at
// camera.focal_distance — rays from a lens point aim at where the pinhole ray through the same
// screen point meets the focal plane) and at a time in the shutter interval [0, camera.shutter]
// (objects with a velocity are moved by velocity × time for that ray and all the rays it casts).
// An area light (a rectangle or a disc) is sampled by light.samples shadow rays, each to its own
// point of the area, each adding 1/samples of that point's diffuse and specular terms; a glossy
// material (gloss > 0) reflects gloss_samples rays about the mirror direction with the Phong
// lobe's density ∝ cos^gloss of their angle to it, each weighted k_r / gloss_samples (a ray drawn
// below the surface adds nothing). Every random number comes from one generator per pixel,
// seeded by mix_seed(settings.seed, i, j), in the order the plain tracer uses them, so an image
// does not depend on the number of threads, and with one sample, no aperture, no shutter time, no
// light area and no gloss the tracer is exactly the one above.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "core/shared.hpp"
#include "rays/csg.hpp"
#include "rays/quadric.hpp"
#include "rays/mesh_gen.hpp"
#include "rays/rt_bvh.hpp"
#include "rays/rt_mesh.hpp"
#include "rays/rt_texture.hpp"
#include "sampling/patterns.hpp"

namespace cg::rt {

using Color = glm::dvec3;

struct Material {
    std::string name;
    Color ka{0.1}, kd{0.7}, ks{0.3};  // ambient, diffuse, specular coefficients, ≥ 0
    double shininess = 20;            // p ≥ 0
    Color kr{0.0};                    // share of the mirror ray's colour, ≥ 0
    Color kt{0.0};                    // share of the refracted ray's colour, ≥ 0
    double ior = 1.0;                 // refraction index inside the object, > 0
    double gloss = 0;                 // glossy reflection: the Phong lobe's exponent (0: a mirror)
    int gloss_samples = 1;            // ... and the reflected rays it casts
    MaterialTextures tex;             // texture, solid texture, bump (rays/rt_texture.hpp)
    bool operator==(const Material&) const = default;
};

struct Light {
    bool directional = false;
    glm::dvec3 position{0.0};         // a point light's position
    glm::dvec3 direction{0.0};        // a directional light's direction of travel
    Color intensity{1.0};             // I_i, ≥ 0
    glm::dvec3 attenuation{1, 0, 0};  // c1, c2, c3 (point lights)
    // An area light (point lights only): a rectangle position + a·edge_u + b·edge_v,
    // a, b ∈ [−½, ½], or a disc of `radius` about `position` across `normal`; sampled by
    // `samples` shadow rays (jittered when a square number, else uniform).
    enum class Area : std::uint8_t { None, Rectangle, Disc } area = Area::None;
    glm::dvec3 edge_u{0.0}, edge_v{0.0};
    double radius = 0;
    glm::dvec3 normal{0, 1, 0};
    int samples = 1;
    bool operator==(const Light&) const = default;
};

enum class ObjectKind : std::uint8_t { Quadric, Plane, Triangle, Csg, Mesh };

// A triangle mesh object's triangles (world space) and their hierarchy (rays/rt_mesh.hpp), built
// once when the object is made and shared by every copy of the scene: a mesh of 10⁶ triangles
// is one object whose rays cost about log n tests. Its triangles are numbered as in its input
// (`source[k]` is triangle k's number there when some were left out as degenerate).
struct TriangleMesh {
    mesh::Mesh mesh;                   // vertices, unit normals (smooth) or none, (u, v) or none
    std::vector<std::uint32_t> source;  // empty: triangle k is input triangle k
    MeshBvh bvh;
    double reach = 0;  // the largest |corner| of its triangles (the scene's size, for ε)
    std::uint32_t source_index(std::size_t k) const {
        return source.empty() ? static_cast<std::uint32_t>(k) : source[k];
    }
    // The hierarchy and the reach follow from the triangles.
    bool operator==(const TriangleMesh& o) const { return mesh == o.mesh && source == o.source; }
};
// Builds the hierarchy. Preconditions: finite vertices, valid indices, `normals` empty or unit
// (one per vertex), `uv` empty or one per vertex.
TriangleMesh make_triangle_mesh(mesh::Mesh m, std::vector<std::uint32_t> source = {});

struct Object {
    ObjectKind kind = ObjectKind::Quadric;
    std::string name;   // as given, or "objects[3]" / "objects[3].triangles[5]"
    std::string field;  // where the object is in the input, for errors: "objects[3]"
    int material = 0;   // index into Scene::materials
    Quadric quadric;    // Quadric
    glm::dvec3 p0{0.0}, p1{0.0}, p2{0.0};  // Triangle vertices; Plane: p0 is a point on it
    glm::dvec3 normal{0, 0, 1};            // Plane: as given (any length > 0)
    bool smooth = false;                   // Triangle: vertex normals given (smooth shading):
    glm::dvec3 n0{0.0}, n1{0.0}, n2{0.0};  // ... at p0, p1, p2 (any length > 0)
    CsgTree csg;                           // Csg: the tree (rays/rt_csg.hpp)
    Shared<TriangleMesh> mesh;             // Mesh: its triangles and their hierarchy
    ObjectUv uv;                           // its texture parametrisation (rays/rt_texture.hpp)
    glm::dvec3 velocity{0.0};              // motion blur: moved by velocity × time
    bool operator==(const Object&) const = default;
};

struct Camera {
    glm::dvec3 eye{0, 0, 5}, center{0, 0, 0}, up{0, 1, 0};
    double fov_y_deg = 45;        // vertical field of view, degrees, in (0, 180)
    int width = 64, height = 48;  // pixels
    double aperture = 0;          // depth of field: the thin lens's radius (0: a pinhole)
    double focal_distance = 0;    // ... the distance in focus along the view (0: |center − eye|)
    double shutter = 0;           // motion blur: rays are spread over times [0, shutter]
    bool operator==(const Camera&) const = default;
};

enum class Model : std::uint8_t { Phong, BlinnPhong };

struct Settings {
    int max_depth = 3;  // reflection/refraction depth limit: 0 casts no secondary rays
    bool shadows = true, reflections = true, refractions = true;
    Model model = Model::Phong;
    int samples_per_pixel = 1;  // primary rays per pixel (anti-aliasing)
    sampling::Pattern pattern = sampling::Pattern::Jittered;  // where they go in the pixel
    sampling::Filter filter = sampling::Filter::Box;          // how they are weighted
    std::uint64_t seed = 1;                                   // every random choice comes from it
    bool operator==(const Settings&) const = default;
};

struct Scene {
    Camera camera;
    Settings settings;
    Color background{0.0};
    Color ambient{0.1};  // I_a
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<Object> objects;
    bool operator==(const Scene&) const = default;
};

// Limits, so that an input cannot make a run exhaust the machine; refused with a clear error.
constexpr long long kMaxPixels = 4096LL * 4096;
constexpr int kMaxDepth = 16;
constexpr std::size_t kMaxObjects = 20000;         // objects; and ray-object tests per ray
constexpr std::size_t kMaxTriangles = 1u << 22;    // 4,194,304 triangles in all the meshes
constexpr std::size_t kMaxLights = 64;
constexpr double kMaxCoordinate = 1e12;  // |coordinates| and scene sizes stay below this
constexpr double kMaxAttenuation = 1e6;  // 1/(c1 + c2 r + c3 r²) is capped here (a light at r = 0)
constexpr int kMaxSamplesPerPixel = 1024;
constexpr int kMaxLightSamples = 1024;
constexpr int kMaxGlossSamples = 256;

// What a scene spreads its rays over, effect by effect (Cook's table, the course's exam
// question): anti-aliasing spreads the primary rays over the pixel's area (more than one sample
// per pixel), depth of field over the lens aperture (aperture > 0), motion blur over the shutter
// time (shutter > 0); soft shadows spread the shadow rays over the light's area (an area light),
// glossy reflection spreads the reflected rays over the Phong lobe about the mirror direction (a
// material with gloss > 0).
struct Distribution {
    bool anti_aliasing = false, depth_of_field = false, motion_blur = false;
    bool soft_shadows = false, glossy_reflection = false;
    bool any() const {
        return anti_aliasing || depth_of_field || motion_blur || soft_shadows || glossy_reflection;
    }
    bool operator==(const Distribution&) const = default;
};
Distribution distribution(const Scene& s);
// Whether the scene uses any distribution. Without any, every ray is traced as before.
inline bool distributed(const Scene& s) { return distribution(s).any(); }

// The cost of a scene in ray-object tests: every ray of a primary ray's tree (a full binary
// tree of depth max_depth when some materials mirror and others refract — or one does both —,
// a chain when only one kind does) meets every object and casts a shadow ray to every light.
// An object costs one test, a CSG object one per leaf (object_tests), and a mesh what its
// hierarchy costs a ray that meets its box, expected (MeshBvh::cost: the surface area
// heuristic's box and triangle tests, about 4 log₄ n for n triangles spread out, up to n when
// they all overlap). The objects are counted one by one although the scene's own hierarchy
// (rt_bvh.hpp) usually tests far fewer: every object can overlap every ray.
double tree_rays(const Scene& s);      // rays in one primary ray's tree, at most (glossy
                                       // materials branch gloss_samples ways)
double scene_tests(const Scene& s);    // ray-object tests per ray: objects, CSG leaves each,
                                       // meshes their hierarchy's cost
std::size_t scene_triangles(const Scene& s);  // triangles in all the meshes
double pixel_work(const Scene& s);     // samples × tree_rays × (1 + shadow rays) × scene_tests
                                       // (+ samples² for Poisson dart throwing)
constexpr double kMaxPixelWork = 1e7;  // one pixel (one step): well under a second
constexpr double kMaxWork = 2e10;      // the whole image: a few minutes at most

// Throws InputError naming p[k] ("camera.eye[2]") unless every coordinate is finite and within
// ±kMaxCoordinate.
void check_coordinates(glm::dvec3 p, const std::string& field);

// Throws InputError naming the field ("camera.fov_y_deg", "objects[2].material",
// "lights[0].attenuation"). Fields are named as in the JSON scene format (rt_scene_json.hpp).
void validate(const Scene& s);

// ---- what the tracer needs, computed once per scene -------------------------------------

struct PreparedObject {
    ObjectKind kind = ObjectKind::Quadric;
    int material = 0;
    PreparedQuadric quadric;
    glm::dvec3 p0{0.0}, e1{0.0}, e2{0.0};  // a triangle's p0, p1 − p0, p2 − p0
    glm::dvec3 normal{0.0};                // a plane's or triangle's unit normal
    bool smooth = false;                   // a triangle with vertex normals ...
    glm::dvec3 n0{0.0}, n1{0.0}, n2{0.0};  // ... unit, at p0, p1, p2
    Shared<PreparedCsg> csg;               // a CSG object's tree
    Shared<TriangleMesh> mesh;             // a mesh object's triangles (the Object's, shared)
    glm::dvec3 velocity{0.0};              // motion blur (rays are moved by −velocity × time)
    bool moving = false;                   // velocity ≠ 0
    bool operator==(const PreparedObject&) const = default;
};

// The camera's look-at frame and the screen's half sizes.
struct View {
    glm::dvec3 eye{0.0}, u{1, 0, 0}, v{0, 1, 0}, w{0, 0, -1};
    double half_height = 1, half_width = 1;
    int width = 1, height = 1;
    bool operator==(const View&) const = default;
};

struct Prepared {
    View view;
    double focal_distance = 1;  // the camera's, resolved (|center − eye| when not given)
    std::vector<PreparedObject> objects;
    double epsilon = 1e-9;     // the offset of secondary rays, scaled to the scene's size
    bool distributed = false;  // rt::distributed(scene)
    ObjectBvh bvh;             // over the objects with finite bounds (rt_bvh.hpp)
    PreparedTextures textures;
    bool operator==(const Prepared&) const = default;
};
// Precondition: validate(s) does not throw.
Prepared prepare(const Scene& s);

View make_view(const Camera& c);
// The point of pixel coordinates (x, y) (pixel units from the screen's bottom-left corner; the
// centre of pixel (i, j) is (i + ½, j + ½)) on the screen, and the primary ray's d = P − E.
glm::dvec3 screen_point(const View& v, double x, double y);

struct Hit {
    int object = -1;    // -1: nothing hit
    int triangle = -1;  // a mesh object's triangle hit (its index in TriangleMesh::mesh)
    double t = 0;
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0};  // unit, turned to face the ray (−d side)
    bool entering = true;    // the ray met the geometric normal head-on: it enters the solid
    bool operator==(const Hit&) const = default;
};

// The nearest hit with t > t_min (and t < t_max) over every object, at `time` (moving objects
// are where velocity × time puts them).
Hit nearest_hit(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction,
                double t_min = kRayEpsilon, double t_max = Quadric::kInf, double time = 0);
// Whether anything lies on the ray at t_min < t < t_max (a shadow ray's test): the first
// object found, or -1.
int first_blocker(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction, double t_min,
                  double t_max, double time = 0);
// The same answers by testing every object in turn: the reference the hierarchy is checked
// against (tests, benchmark).
Hit nearest_hit_brute_force(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction,
                            double t_min = kRayEpsilon, double t_max = Quadric::kInf,
                            double time = 0);
int first_blocker_brute_force(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction,
                              double t_min, double t_max, double time = 0);
// What nearest_hit's search costs for this ray: the boxes it tests (the root's and both
// children's of every inner node it opens) and the objects it tests (those tested for every
// ray included); brute force tests every object.
struct TraversalCounts {
    long long box_tests = 0, object_tests = 0;
};
TraversalCounts traversal_counts(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction,
                                 double t_min = kRayEpsilon, double t_max = Quadric::kInf,
                                 double time = 0);
// Whether any object lies on the ray at t_min < t < t_max: first_blocker(…) ≥ 0, found
// sooner (the first blocker met, not the one with the smallest index).
bool blocked(const Prepared& p, glm::dvec3 origin, glm::dvec3 direction, double t_min,
             double t_max, double time = 0);
// An object's bounding box (world space), or the empty box when it has none: planes, CSG
// objects, moving objects, quadrics not closed or not cut by a z slab on both sides.
Bounds object_bounds(const Object& o);
// The hit's t with one object (or +inf), and its normal there: the pieces of nearest_hit. A CSG
// object's normal depends on which surface the ray met, not only on the point: object_normal
// takes the ray too.
double intersect_object(const PreparedObject& o, glm::dvec3 origin, glm::dvec3 direction,
                        double t_min);
glm::dvec3 object_normal(const PreparedObject& o, glm::dvec3 point, glm::dvec3 origin,
                         glm::dvec3 direction, double t_min);

// ---- shading and the secondary rays (shared by the plain tracer and the state machine) ----

// What one light does at a hit: its direction, distance and attenuation, and, if it is in
// front of the surface, its diffuse and specular terms (the shadow test decides whether they
// are added).
struct LightTerm {
    glm::dvec3 l{0.0};                // unit, toward the light
    double distance = Quadric::kInf;  // to a point light; +inf for a directional one
    double attenuation = 1;
    double n_dot_l = 0;
    double spec_dot = 0;  // r·v (Phong) or h·n (Blinn-Phong), raw
    Color diffuse{0.0}, specular{0.0};
    bool facing = false;  // n·l > 0: the light is in front of the surface
    bool operator==(const LightTerm&) const = default;
};
LightTerm light_term(const Scene& s, const Light& light, const Material& m, glm::dvec3 point,
                     glm::dvec3 n, glm::dvec3 v);
// The same with the diffuse colour k_d given (a textured surface's, rays/rt_texture.hpp).
LightTerm light_term(const Scene& s, const Light& light, const Color& kd, const Material& m,
                     glm::dvec3 point, glm::dvec3 n, glm::dvec3 v);
// The shadow ray's start: the hit point nudged off the surface toward the light.
glm::dvec3 offset_point(const Prepared& p, glm::dvec3 point, glm::dvec3 toward);

// Mirror direction of a unit d about the unit n (n facing −d): r = d − 2 (d·n) n.
glm::dvec3 reflect(glm::dvec3 d, glm::dvec3 n);
// Refracted unit direction by Snell's law for unit d and unit n facing −d, η = η₁/η₂; false at
// total internal reflection (η² (1 − cos²θ₁) > 1).
bool refract(glm::dvec3 d, glm::dvec3 n, double eta, glm::dvec3& out);

// surface_at (rays/rt_texture.hpp) for a hit at `time`: a moving object's textures are looked up
// where the hit is on the object at rest.
Surface moving_surface_at(const Scene& s, const Prepared& p, const Hit& h, glm::dvec3 origin,
                          glm::dvec3 d, const RayDifferential* diff, double time,
                          SurfaceDetail* detail);

// A hit's secondary rays, as both tracers cast them (unit d, the incoming direction):
// the mirror ray from just above the surface; and the transmitted one — refracted from just
// below it by η = 1/ior entering and ior leaving, or, at total internal reflection, the
// mirror ray instead.
struct SecondaryRay {
    glm::dvec3 origin{0.0}, direction{0.0};
    bool refracted = false;       // a refracted ray (else a mirror ray)
    bool total_internal = false;  // the mirror ray cast because no refracted ray exists
};
SecondaryRay mirror_ray(const Prepared& p, const Hit& h, glm::dvec3 d);
SecondaryRay transmitted_ray(const Prepared& p, const Hit& h, glm::dvec3 d, double ior);

// ---- distribution: the random choices, shared by the plain tracer and the state machine ----

// One primary ray of a pixel: where it crosses the pixel (pixel units), the lens point (in the
// lens's u, v frame, lens radii) and the time, and its filter weight.
struct PixelSample {
    glm::dvec2 pixel{0.5};  // offset in the pixel, [0, 1)²
    glm::dvec2 lens{0.0};   // in the unit disc
    double time = 0;
    double weight = 1;
    bool operator==(const PixelSample&) const = default;
};
// The pixel's generator, and its samples (drawing the lens points and times from it).
Rng pixel_rng(const Scene& s, int i, int j);
std::vector<PixelSample> pixel_samples(const Scene& s, int i, int j, Rng& rng);
// The primary ray of a sample: origin (the eye, or a point of the lens) and direction.
void primary_ray(const Prepared& p, const Camera& c, int i, int j, const PixelSample& ps,
                 glm::dvec3& origin, glm::dvec3& direction);
// The points an area light is sampled at for one hit (drawn from rng; `light.samples` of them).
std::vector<glm::dvec3> light_points(const Light& light, Rng& rng);
// A glossy ray's direction about the unit mirror direction r: cos θ = ξ₁^(1/(gloss+1)).
glm::dvec3 glossy_direction(glm::dvec3 r, double gloss, Rng& rng);

// Whether any channel is positive: a material mirrors when any_positive(kr), refracts when
// any_positive(kt).
inline bool any_positive(const Color& c) {
    return c.x > 0 || c.y > 0 || c.z > 0;
}

// How many rays of each kind a trace cast.
struct RayCounts {
    std::uint64_t primary = 0, shadow = 0, reflected = 0, refracted = 0;
    std::uint64_t total() const { return primary + shadow + reflected + refracted; }
    RayCounts& operator+=(const RayCounts& o) {
        primary += o.primary, shadow += o.shadow, reflected += o.reflected,
            refracted += o.refracted;
        return *this;
    }
    bool operator==(const RayCounts&) const = default;
};

// ---- the plain tracer ---------------------------------------------------------------------

// The colour a ray returns; `depth` is how many reflections/refractions led to it; `diff` is a
// primary ray's differential, for mipmapped textures (rays/rt_texture.hpp); `rng` the pixel's
// generator (needed when the scene has area lights or glossy materials), `time` the ray's.
Color trace(const Scene& s, const Prepared& p, glm::dvec3 origin, glm::dvec3 direction, int depth,
            RayCounts& counts, const RayDifferential* diff = nullptr, Rng* rng = nullptr,
            double time = 0);
Color pixel_color(const Scene& s, const Prepared& p, int i, int j, RayCounts& counts);

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint32_t> rgba;  // width × height, row 0 at the BOTTOM (as pixels (i, j))
    RayCounts rays;
    bool operator==(const Image&) const = default;
};
// The whole image, rows shared between `threads` threads (0: one per core). The image does not
// depend on the number of threads.
Image render(const Scene& s, int threads = 0);

}  // namespace cg::rt
