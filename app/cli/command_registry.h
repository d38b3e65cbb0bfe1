#pragma once

#include <functional>

#include <CLI/CLI.hpp>

#include "base/program/static_registry.h"

namespace raystep {

/// A subcommand as added to the command line: the parser that knows it was given, and what runs it.
struct AddedCommand {
    CLI::App* command = nullptr;
    std::function<int()> run;
};

/// Adds a subcommand to the `raystep` command line. Most commands of app/ are added by main.cpp
/// itself, and one in a file of its own (`submit`) through CommandRegistry; a layer above app/
/// adds its own (the studies' `bench`) through CommandRegistry, so that app/ never names it and a
/// student release, which leaves that layer out, has no such command.
using AddCommand = AddedCommand (*)(CLI::App& app);
using CommandRegistry = StaticRegistry<AddCommand>;

}  // namespace raystep
