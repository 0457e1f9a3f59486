// Copyright (c) 2026 VVM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fuzz target: the command line of vvm-mesh (tools/vvm-mesh/command_line.h). The input is
// the arguments, separated by NUL bytes; they are parsed and turned into the front end's
// options of the command, as the program does before any work.

#include "fuzz_target.h"

#include "command_line.h"

#include <vector>

VVM_FUZZ_TARGET(vvm_mesh_arguments)
{
  namespace CL = vvm::command_line;
  std::vector<std::string> arguments{"vvm-mesh"};
  std::string current;
  for(std::size_t i = 0; i < size; ++i) {
    if(data[i] == 0) {
      arguments.push_back(current);
      current.clear();
    } else {
      current += char(data[i]);
    }
  }
  arguments.push_back(current);
  std::vector<const char*> argv;
  for(const std::string& a : arguments) argv.push_back(a.c_str());
  try {
    const CL::Arguments a = CL::with_output_extension(CL::parse(int(argv.size()), argv.data()));
    if(a.help) return 0;
    if(a.command == "tet") (void)CL::tet_options(a);
    else if(a.command == "hexdom") (void)CL::hex_dominant_options(a);
    else if(a.command == "optimize") (void)CL::optimize_options(a);
    else if(a.command == "field") (void)CL::field_options(a);
    else if(a.command == "surface") (void)CL::surface_options(a);
    else if(a.command != "quality") vvm_fuzz::fuzz_failure("parse() accepted the command '" + a.command + "'");
    if(a.input.empty()) vvm_fuzz::fuzz_failure("parse() accepted a command line without input");
  } catch(const std::invalid_argument&) {
  }
  return 0;
}
