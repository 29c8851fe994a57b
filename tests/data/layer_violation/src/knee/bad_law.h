#pragma once
// Fixture for the layer_check_catches_upward_include test: a knee law including the swing layer.
#include "swing/swing_simulation.h"
