#include "app/version.hpp"

namespace spiral::app {
const char* const kVersion = SPIRAL_VERSION;
const char* const kGitCommit = SPIRAL_GIT_COMMIT;
}  // namespace spiral::app
