// semimesh command line: dispatches subcommands and maps failures to exit codes (exit_codes.hpp).
#include "cad_info.hpp"
#include "check_command.hpp"
#include "exit_codes.hpp"
#include "init_command.hpp"
#include "run_command.hpp"

#include "semimesh/backends/builtin.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <iostream>

namespace {

using namespace semimesh::app;

int run(int argc, char** argv) {
  CLI::App app{"semimesh: valid high-order curvilinear hybrid meshes around wings on a wall"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("semimesh ") + SEMIMESH_VERSION);

  CadInfoOptions cad_info;
  CLI::App* cad_info_cmd = app.add_subcommand("cad-info", "Load a CAD model and list its surfaces, curves, box and units");
  cad_info_cmd->add_option("--backend", cad_info.backend,
                           "CAD backend: naca, occ, vendor (default: from the file extension, or naca without a file)");
  cad_info_cmd->add_flag("--json", cad_info.json, "Print one JSON object instead of tables");
  cad_info_cmd->add_option("--param", cad_info.params, "Backend parameter key=value, e.g. naca.code=2412 (repeatable)");
  cad_info_cmd->add_option("source", cad_info.source, "CAD file (.step .stp .iges .igs .brep .brp .fcstd) or backend source");

  CheckOptions check_options;
  CLI::App* check_cmd = add_check_subcommand(app, check_options);
  RunOptions run_options;
  CLI::App* run_cmd = add_run_subcommand(app, run_options);
  InitOptions init_options;
  CLI::App* init_cmd = add_init_subcommand(app, init_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "semimesh: error: " << e.what() << " (see semimesh --help)\n";
    return kExitBadInput;
  }

  if (cad_info_cmd->parsed()) {
    run_cad_info(semimesh::backends::default_registry(), cad_info, std::cout);
    return kExitOk;
  }
  if (run_cmd->parsed()) {
    run_options.terminal = isatty(STDOUT_FILENO) != 0;
    return run_pipeline_command(run_options, std::cout, std::cerr);
  }
  if (check_cmd->parsed()) return run_check_command(check_options, std::cout, std::cerr);
  if (init_cmd->parsed()) return run_init_command(init_options, std::cout, std::cerr);
  return kExitBadInput;
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // glibc raises its mmap threshold whenever a large block is freed; the stages' later large arrays
  // then come from the heap, whose freed room stays resident (measured: 21 of the 519 MiB peak of the
  // paper's case at order 3). A fixed threshold gives every large array back to the system when freed.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  try {
    return run(argc, argv);
  } catch (const semimesh::Error& e) {
    const bool input = e.cause() == semimesh::Error::Cause::BadInput;
    std::cerr << "semimesh: " << (input ? "error: " : "internal error: ") << e.what() << "\n";
    return exit_code(e.cause());
  } catch (const std::exception& e) {
    std::cerr << "semimesh: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "semimesh: internal error: unknown exception\n";
    return kExitInternal;
  }
}
