// semimesh command line: dispatches subcommands and maps failures to exit codes
// (DESIGN.md section 7: 0 ok, 1 bad input, 2 invalid mesh produced, 3 internal error).
#include "cad_info.hpp"

#include "semimesh/backends/builtin.hpp"
#include "semimesh/cad/error.hpp"
#ifdef SEMIMESH_HAVE_IO
#include "semimesh/io/check.hpp"
#endif
#ifdef SEMIMESH_HAVE_PIPELINE
#include "run_command.hpp"
#endif

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitInternal = 3;

bool is_input_error(semimesh::cad::CadError::Kind kind) { return kind != semimesh::cad::CadError::Kind::Geometry; }

int run(int argc, char** argv) {
  CLI::App app{"semimesh: valid high-order curvilinear hybrid meshes around wings on a wall"};
  app.require_subcommand(1);

  semimesh::app::CadInfoOptions cad_info;
  CLI::App* cad_info_cmd = app.add_subcommand("cad-info", "Load a CAD model and list its surfaces, curves, box and units");
  cad_info_cmd->add_option("--backend", cad_info.backend,
                           "CAD backend: naca, occ, vendor (default: from the file extension, or naca without a file)");
  cad_info_cmd->add_flag("--json", cad_info.json, "Print one JSON object instead of tables");
  cad_info_cmd->add_option("--param", cad_info.params, "Backend parameter key=value, e.g. naca.code=2412 (repeatable)");
  cad_info_cmd->add_option("source", cad_info.source, "CAD file (.step .stp .iges .igs .brep .brp .fcstd) or backend source");

#ifdef SEMIMESH_HAVE_IO
  CLI::App* check_cmd = app.add_subcommand("check", "Check the validity and quality of a mesh file (MESH.msh [--json])");
  check_cmd->prefix_command();
  check_cmd->allow_extras();
#endif

#ifdef SEMIMESH_HAVE_PIPELINE
  // ---- `semimesh run`: options and logic in apps/run_command.cpp ----
  semimesh::app::RunOptions run_options;
  CLI::App* run_cmd = semimesh::app::add_run_subcommand(app, run_options);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "semimesh: error: " << e.what() << " (see semimesh --help)\n";
    return kExitBadInput;
  }

  if (cad_info_cmd->parsed()) {
    semimesh::app::run_cad_info(semimesh::backends::default_registry(), cad_info, std::cout);
    return kExitOk;
  }
#ifdef SEMIMESH_HAVE_PIPELINE
  if (run_cmd->parsed()) return semimesh::app::run_pipeline_command(run_options, std::cout, std::cerr);
#endif
#ifdef SEMIMESH_HAVE_IO
  if (check_cmd->parsed()) return semimesh::io::run_check(check_cmd->remaining(), std::cout, std::cerr);
#endif
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const semimesh::cad::CadError& e) {
    if (is_input_error(e.kind())) {
      std::cerr << "semimesh: error: " << e.what() << "\n";
      return kExitBadInput;
    }
    std::cerr << "semimesh: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "semimesh: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "semimesh: internal error: unknown exception\n";
    return kExitInternal;
  }
}
