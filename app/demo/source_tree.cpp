#include "app/demo/source_tree.h"

namespace raystep {

std::filesystem::path source_tree() {
    return RAYSTEP_SOURCE_DIR;
}

}  // namespace raystep
