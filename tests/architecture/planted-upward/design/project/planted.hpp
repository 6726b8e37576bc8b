#pragma once
// A planted upward include: the include-direction check must fail on this tree.
#include "design/stages/static_stage.hpp"
