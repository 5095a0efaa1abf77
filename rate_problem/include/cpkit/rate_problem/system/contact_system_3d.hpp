#pragma once
/// \file contact_system_3d.hpp
/// The system file with three-dimensional points ("dim": 3): ContactSystem3d =
/// ContactSystemOf<3>, declared with the 2-D system in contact_system.hpp (one type, one
/// reader). Kept so that the files that include this name need not change.
#include "cpkit/rate_problem/system/contact_system.hpp"
