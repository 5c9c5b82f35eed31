// Writes the occ backend's B-spline NACA wing as a third-party CAD file of one of the kinds users
// bring (issue "your own wing CAD as it comes"), for end-to-end tests of `init --cad` and `run`:
//
//   write_wing_variant VARIANT OUT.step [naca.key=value ...]
//
//   asis    the shape as the backend builds it (with naca.farfield=false: the body alone, its root
//           section left open: free curves in the wall plane, as wing CAD is often exported);
//   nurbs   every face converted to a B-spline (BRepBuilderAPI_NurbsConvert), as many CAD tools
//           export: the wall and the box faces are planar B-splines, not planes;
//   capped  every open planar loop closed by a planar face and sewn on (with naca.farfield=false: a
//           closed body whose root is a planar cap, like the ONERA M6 file).
//
// Exit 0 on success, 1 with a message on stderr otherwise.
#include "semimesh/occ/occ_backend.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <iostream>
#include <string>

namespace {

TopoDS_Shape capped(const TopoDS_Shape& shape) {
  ShapeAnalysis_FreeBounds bounds(shape, 1e-7, /*splitclosed=*/false, /*splitopen=*/true);
  BRepBuilderAPI_Sewing sewing(1e-7);
  sewing.Add(shape);
  for (TopExp_Explorer w(bounds.GetClosedWires(), TopAbs_WIRE); w.More(); w.Next())
    sewing.Add(BRepBuilderAPI_MakeFace(TopoDS::Wire(w.Current()), /*OnlyPlane=*/true).Face());
  sewing.Perform();
  return sewing.SewedShape();
}

TopoDS_Shape variant(const std::string& name, const TopoDS_Shape& wing) {
  if (name == "asis") return wing;
  if (name == "nurbs") return BRepBuilderAPI_NurbsConvert(wing, /*Copy=*/true).Shape();
  if (name == "capped") return capped(wing);
  throw std::invalid_argument("unknown variant '" + name + "' (known: asis, nurbs, capped)");
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
