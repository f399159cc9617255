// Photon map exam problems: a point light of power Φ (100 to 1000 W) at height h (1 or 2) over a
// black floor (albedo 0: every photon that lands is stored, then absorbed), N photons (20 to 100),
// and x = (0, 0, 0) right under the light. The question gives the distances of the k = 4 photons
// nearest x (from the run) and asks for the power they carry, the estimate E ≈ Σ Φ_p / (π r²),
// and the exact direct irradiance Φ / (4π h²) it approximates.
#include "core/format.hpp"
#include "gi/photon_map.hpp"

namespace cg {

PhotonMap::Input PhotonMap::exam_input(Rng& rng) {
    static constexpr double kPowers[] = {100, 200, 400, 500, 1000};
    static constexpr int kCounts[] = {20, 40, 50, 100};
    Input in;
    Object floor;
    floor.shape = Shape::Plane;
    floor.center = {0, 0, 0};
    floor.normal = {0, 1, 0};
    floor.albedo = 0;
    in.objects = {floor};
    Light l;
    l.position = {0, double(rng.integer(1, 2)), 0};
    l.power = kPowers[rng.integer(0, 4)];
    in.lights = {l};
    in.photons = kCounts[rng.integer(0, 3)];
    in.seed = std::uint64_t(rng.integer(1, 1000));
    in.query = {0, 0, 0};
    in.k = 4;
    return in;
}

std::string PhotonMap::question(const Input& in) {
    const Result r = compute(in);
    const Light& l = in.lights[0];
    std::string d;
    for (std::size_t i = 0; i < r.distances.size(); ++i)
        d += (i ? ", " : "") + num(r.distances[i], 4);
    return "A point light of power Φ = " + num(l.power) + " W at " + num(l.position) + " emits N = " +
           std::to_string(in.photons) +
           " photons uniformly over all directions, each carrying the same share of Φ. About half "
           "land on the black floor y = 0, where each is stored (and then absorbed). The " +
           std::to_string(r.distances.size()) + " stored photons nearest x = (0, 0, 0) are at distances " +
           d + ". Give the power they carry together (sum_power), the photon-map estimate of the "
           "irradiance E ≈ Σ Φ_p / (π r²) with r the largest of those distances (irradiance), and the "
           "exact direct irradiance at x, Φ / (4π h²) with h the light's height (direct_irradiance).";
}

std::vector<std::string> PhotonMap::answer_fields() {
    return {"sum_power", "irradiance", "direct_irradiance"};
}

}  // namespace cg
