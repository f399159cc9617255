// OBJ files, through the ray tracer's mesh reader (rays/mesh_json.hpp): the bytes are written to
// a file and read. Only InputError may escape, and its message names the field; a mesh that is
// read has triangles whose indices are in range, finite vertices, one unit-length-able normal
// and one (u, v) per vertex when it has any, and no triangle of zero area.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>

#include "fuzz_support.hpp"
#include "rays/mesh_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string path = (std::filesystem::temp_directory_path() /
                                     ("cg_fuzz_obj_" + std::to_string(::getpid()) + ".obj"))
                                        .string();
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        if (!f) cg::fuzz::fail("cannot write the temporary file");
        if (size > 0 && std::fwrite(data, 1, size, f) != size) cg::fuzz::fail("short write");
        std::fclose(f);
    }
    cg::mesh::Mesh m;
    try {
        m = cg::mesh_json::read_obj(path, "objects[0].obj");
    } catch (const cg::InputError& e) {
        if (e.field() != "objects[0].obj") cg::fuzz::fail("an error naming another field");
        return 0;
    }
    if (m.triangles.empty()) cg::fuzz::fail("a mesh read without triangles");
    if (!m.normals.empty() && m.normals.size() != m.vertices.size())
        cg::fuzz::fail("normals not one per vertex");
    if (!m.uv.empty() && m.uv.size() != m.vertices.size()) cg::fuzz::fail("uv not one per vertex");
    for (const glm::dvec3& p : m.vertices)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            cg::fuzz::fail("a non-finite vertex");
    for (const glm::dvec3& n : m.normals)
        if (!(glm::length(n) > 0) || !std::isfinite(glm::length(n)))
            cg::fuzz::fail("a zero normal");
    for (const auto& t : m.triangles) {
        for (std::uint32_t k : t)
            if (k >= m.vertices.size()) cg::fuzz::fail("a triangle index out of range");
        if (cg::mesh::degenerate(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]))
            cg::fuzz::fail("a degenerate triangle kept");
    }
    return 0;
}
