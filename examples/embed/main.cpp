// The stages of `semimesh run`, called one by one from a program of your own (docs/library.md):
// an analytic NACA 0012 wing through the backend registry, surface meshes, the near-field shell,
// the far field, curving at order 3, splitting into 4 layers, certification, an MSH file. Curving and
// certification report their progress (semimesh/progress.hpp) to a callback of ours: a line per quarter.
//   embed OUTPUT.msh
#include "semimesh/backends/builtin.hpp"
#include "semimesh/farfield/far_field.hpp"
#include "semimesh/ho/curving/curve_mesh.hpp"
#include "semimesh/ho/mesh_validity.hpp"
#include "semimesh/ho/splitting/split_layers.hpp"
#include "semimesh/io/msh.hpp"
#include "semimesh/nearfield/o_shell.hpp"
#include "semimesh/progress.hpp"
#include "semimesh/surface/model_surfaces.hpp"

#include <iostream>
#include <string>

using namespace semimesh;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: embed OUTPUT.msh\n";
    return 1;
  }
  try {
    // 1. The CAD model, chosen by name: a unit-span NACA 0012 wing in a small box.
    cad::Source source;
    source.params.set("naca.span", "1");
    source.params.set("naca.box", "-3,-3,0,4,3,3");
    const std::unique_ptr<cad::Model> model = backends::default_registry().load("naca", source);
    auto surface = [&](const char* name) { return *model->find_surface(name); };

    // 2. Surface meshes from a size field.
    surface::SizeParams size;
    size.max_size = 1.0;
    size.min_size = 0.02;
    size.le_size = 0.06;
    size.te_size = 0.03;
    size.curvature_segments = 2;
    const surface::SurfaceMeshes surfaces = surface::mesh_model_surfaces(*model, surface::SizeField(*model, size));

    // 3. One layer of prisms around the body, 4. the far field around it.
    nearfield::ShellParams shell;
    shell.thickness = 0.05;
    const nearfield::BodyRoles roles{{surface("upper"), surface("lower"), surface("te_base"), surface("tip")},
                                     surface("wall")};
    nearfield::NearField near = nearfield::build_o_shell(*model, surfaces, roles, shell);
    farfield::FarFieldParams far;
    far.box_size = 1.0;
    far.wall_size = 0.6;
    const std::vector<int> box = {surface("box_xmin"), surface("box_xmax"), surface("box_ymin"), surface("box_ymax"),
                                  surface("box_zmax")};
    const farfield::FarField linear = farfield::build_far_field(*model, std::move(near), far, box, roles.wall_surface);

    // Progress of the two longest calls, curving (first half) and certification (second half).
    int quarters_shown = 0;
    const ProgressCallback show = [&](double fraction, const std::string& step) {
      for (; quarters_shown <= static_cast<int>(4 * fraction); ++quarters_shown)
        std::cerr << "progress " << 25 * quarters_shown << "% (" << step << ")\n";
    };

    // 5. Order 3 on the CAD, 6. the prisms split into 4 layers growing by 1.5.
    ho::CurvingParams curving;
    curving.order = 3;
    const mesh::Mesh curved = ho::curve_mesh(linear.mesh, *model, curving, nullptr, progress_part(show, 0.0, 0.5));
    std::vector<std::size_t> prisms;
    for (std::size_t e = 0; e < curved.elements().size(); ++e)
      if (curved.elements()[e].shape == ho::Shape::Prism) prisms.push_back(e);
    const mesh::Mesh split = ho::split_layers(curved, prisms, ho::LayerDistribution{4, 1.5});

    // 7. Every element certified, 8. the file.
    const ho::MeshValidity validity = ho::certify_mesh(split, 8, 0.0, progress_part(show, 0.5, 1.0));
    io::write_msh(split, argv[1]);
    std::cout << split.elements().size() << " elements, " << validity.invalid << " invalid, min scaled Jacobian "
              << validity.min_scaled_jacobian << "\n";
    return validity.all_valid() ? 0 : 2;
  } catch (const Error& e) {
    std::cerr << "embed: " << e.what() << "\n";
    return 1;
  }
}
