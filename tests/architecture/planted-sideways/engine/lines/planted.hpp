#pragma once
// A planted sideways include (lines and hull share a rank): the check must fail on this tree.
#include "engine/hull/hydrostatics.hpp"
