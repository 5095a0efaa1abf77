#pragma once
/// \file core.hpp
/// Convenience header: everything in cpkit::core.
#include "cpkit/core/errors.hpp"
#include "cpkit/core/finalize.hpp"
#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/log.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/report.hpp"
#include "cpkit/core/residuals.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/core/timer.hpp"
