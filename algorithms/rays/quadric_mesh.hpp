// Quadric surfaces as meshes for the 3D canvas: rings of quads around the model z axis, carried
// to the world by the quadric's transform. Shared by ray-quadric's picture and the ray tracer's.
#pragma once

#include <vector>

#include "core/scene.hpp"
#include "rays/quadric.hpp"

namespace cg {

// The largest of the surface's parameters: its size, for picking what to draw.
double largest_param(const Quadric& q);

// The model-space z range worth drawing: a closed surface's own extent, an open one's within
// ±reach (from 0 for a paraboloid), cut to the slab [zmin, zmax]. Empty when lo ≥ hi.
void drawn_z_range(const Quadric& q, double reach, double& z_lo, double& z_hi);

// Appends the surface between z_lo and z_hi (model space) as around × along quads.
void add_quadric_mesh(const Quadric& q, double z_lo, double z_hi, Style style, float alpha,
                      int around, int along, std::vector<Face3>& faces);

}  // namespace cg
