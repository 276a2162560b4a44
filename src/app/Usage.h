// The --help text of each command. The render command's lists of modes, outputs and
// settings come from their tables (render/OutputCatalog.h, core/Settings.h).
#pragma once

#include "app/CommandLine.h"

#include <string>

namespace gi::app {

[[nodiscard]] std::string usage(Command command);

} // namespace gi::app
