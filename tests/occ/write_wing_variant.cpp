// Writes the occ backend's B-spline NACA wing as a third-party CAD file of one of the kinds users
// bring (issue "your own wing CAD as it comes"), for end-to-end tests of `init --cad` and `run`:
//
//   write_wing_variant VARIANT OUT.step [naca.key=value ...]
//
//   nurbs   every face converted to a B-spline (BRepBuilderAPI_NurbsConvert), as many CAD tools
//           export: the wall and the box faces are planar B-splines, not planes.
//
// Exit 0 on success, 1 with a message on stderr otherwise.
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>

#include <iostream>
#include <string>

namespace {

TopoDS_Shape variant(const std::string& name, const TopoDS_Shape& wing) {
  if (name == "nurbs") return BRepBuilderAPI_NurbsConvert(wing, /*Copy=*/true).Shape();
  throw std::invalid_argument("unknown variant '" + name + "' (known: nurbs)");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: write_wing_variant VARIANT OUT.step [naca.key=value ...]\n";
    return 1;
  }
  try {
    semimesh::cad::Params params;
    for (int i = 3; i < argc; ++i) {
      const std::string kv = argv[i];
      const auto eq = kv.find('=');
      if (eq == std::string::npos || kv.rfind("naca.", 0) != 0) throw std::invalid_argument("expected naca.key=value, got '" + kv + "'");
      params.set(kv.substr(0, eq), kv.substr(eq + 1));
    }
    const TopoDS_Shape shape = variant(argv[1], semimesh::occ::make_naca_wing_shape(semimesh::mock_cad::naca_params_from(params)));
    STEPControl_Writer writer;
    if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(argv[2]) != IFSelect_RetDone)
      throw std::runtime_error(std::string("cannot write '") + argv[2] + "'");
    return 0;
  } catch (const Standard_Failure& e) {
    std::cerr << "write_wing_variant: OCC: " << e.GetMessageString() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "write_wing_variant: " << e.what() << "\n";
  }
  return 1;
}
