"""cpkit: complementarity problems (LCP, NCP/MCP) and the contact, friction and wear model of
Stromberg, Johansson & Klarbring (1996). See docs/python.md.

    import cpkit
    r = cpkit.solve([[2, 1], [1, 2]], [-5, -6])      # r.status, r.z, r.w, r.residuals, ...
    s = cpkit.enumerate([[2, 1], [1, 2]], [-5, -6])  # every solution
"""
from . import _cpkit
from .model import ContactParameters, ContactState, Point3d
from .system import ContactSystem, ContactSystem3d, solve_system_rate, system_direction_counts
from .rate import (Rate3dSolutionSet, rate_indicators, solve_rate_3d, solve_rate_problem,
                   solve_system_rate_3d)
from .step import (FacetedStep3dSolutionSet, Step3dSolutionSet, StepChain3dResult,
                   enumerate_step, enumerate_step_3d, multistart_step_3d, solve_step,
                   solve_step_3d, solve_step_3d_faceted)
from .maps import (Map3d, direction_map, param_direction_map, param_direction_map_3d,
                   param_param_map, param_param_map_3d, sphere_map_3d)
from .simulation import (Fretting3dResult, fretting_history, ramp_history, simulate,
                         simulate_fretting_3d)
from .friction import (ContactReport, FrictionErrors, FrictionProblem, FrictionResult,
                       FrictionSolutionSet, GlobalFrictionProblem, GlobalFrictionResult,
                       friction_errors, friction_solutions, friction_solvers, read_fclib,
                       read_fclib_global, solve_friction, solve_friction_global)
from .lcp import cross_verify, enumerate, solve, solve_batch, solve_mcp, solvers
from .results import (TYPE_BITS, BatchResult, CrossVerifyReport, DirectionMap, ParamDirectionMap,
                      ParamParamMap, RateSolutionSet, SimulationResult, SolutionSet, SolveResult,
                      StepSolutionSet, SystemRateSolutionSet)

__version__ = _cpkit.__version__
UNIQUENESS_CLASSES = list(_cpkit.UNIQUENESS_CLASSES)
