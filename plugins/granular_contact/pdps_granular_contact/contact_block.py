"""What makes the generated contact loops fast: contacts are computed a block at a time, in a loop
LLVM turns into SIMD code (four contacts at once on AVX2), with the contact's quantities in
registers rather than in memory.

A pair loop (composition.ContactModel.kernels) runs in three passes over a block of ``BLOCK``
contacts: it finds the touching pairs of its list and gathers what each contact needs from the
particle arrays (separation, radii, masses, velocities, spins, history) into the block's columns
(``block_in``, one column per quantity, ``BLOCK`` contacts long); one loop computes every contact
of the block (the sub-models, inlined) into ``block_out`` (force, the two torques, heat, the new
history); and a last pass adds these to the particles in list order, so forces sum in the same
order as contact by contact and the results are the same to the last bit.

For that loop to become SIMD code:

- each contact's quantities ``c`` and history ``hist`` are arrays on the stack (``stack_array``),
  of sizes fixed when the module is generated, which LLVM keeps in registers once every call that
  touches them is inlined;
- every sub-model and every numba function it calls is inlined (``inline_part``: numba's own
  inlining of the function's Python source, which does not depend on what numba's cache holds), with
  ``math.sqrt`` as LLVM's square root (``math_shim``): numba's ``math.sqrt`` calls the C library's,
  which may set errno and so cannot be vectorised (both give the correctly rounded root);
- divisions do not test for zero (``error_model="numpy"``: a zero divisor gives inf or nan, as in
  C, where the default raises ZeroDivisionError and branches out of the loop);
- LLVM's cost model is told to vectorise (``vectorized``): it judges the if-converted body of a
  contact law unprofitable on this machine's CPU, where it measured 3.4x faster than scalar code
  (the 20,000-bead settling scene: 62 -> 18 ns a contact for the law).

A sub-model written as composition's docstring says needs none of this: its ``compute`` is compiled
again from its source. One that calls something numba cannot inline (a function of another
library, an object's method) still computes the same contacts, in scalar code.
"""

import contextlib
import math
import types as pytypes

import llvmlite.binding as llvm
from numba import njit, types
from numba.core import cgutils
from numba.core.registry import CPUDispatcher
from numba.extending import intrinsic
from numba.np.arrayobj import make_array, populate_array

# what a generated module takes from here
__all__ = ["BLOCK", "HIST_IN", "HIST_OUT", "IN_LIQUID_I", "IN_LIQUID_J", "IN_TEMPERATURE_I", "IN_TEMPERATURE_J",
           "OUT_HEAT", "OUT_LIQUID_FLUX_I", "OUT_LIQUID_FLUX_J", "OUT_LIQUID_I", "OUT_LIQUID_J", "ROW_I", "ROW_J",
           "SLOT_I", "SLOT_J", "TYPE_I", "TYPE_J", "inline_part", "stack_array"]

# contacts a block holds: its columns (about 30 of 8 bytes) stay within the first-level cache
BLOCK = 128

# the columns of block_in: what the gathering pass reads from the particle arrays for a contact,
# then its history (HIST_IN + h)
(IN_DX, IN_DY, IN_DZ, IN_RADIUS_I, IN_RADIUS_J, IN_MASS_I, IN_MASS_J, IN_FROZEN_I, IN_FROZEN_J,
 IN_VX, IN_VY, IN_VZ, IN_WIX, IN_WIY, IN_WIZ, IN_WJX, IN_WJY, IN_WJZ, IN_TEMPERATURE_I, IN_TEMPERATURE_J,
 IN_LIQUID_I, IN_LIQUID_J, HIST_IN) = range(23)
# the columns of block_out: the force on i, the torques on i and on j, the heat into i, the liquid
# contents and fluxes of a wet model, then the contact's history after this step (HIST_OUT + h)
(OUT_FX, OUT_FY, OUT_FZ, OUT_TIX, OUT_TIY, OUT_TIZ, OUT_TJX, OUT_TJY, OUT_TJZ, OUT_HEAT,
 OUT_LIQUID_I, OUT_LIQUID_J, OUT_LIQUID_FLUX_I, OUT_LIQUID_FLUX_J, HIST_OUT) = range(15)
# the columns of block_index: rows i and j, their slots in the contact history, their types
(ROW_I, ROW_J, SLOT_I, SLOT_J, TYPE_I, TYPE_J, INDEX_COLUMNS) = range(7)


@intrinsic
def stack_array(typingctx, size):
    """A float64 array of ``size`` (a literal integer) on the stack of the calling function: no
    allocation, and LLVM keeps it in registers where every index into it is a constant."""
    if not isinstance(size, types.IntegerLiteral):
        return None
    n = size.literal_value
    array_type = types.Array(types.float64, 1, "C")

    def codegen(context, builder, signature, args):
        data = cgutils.alloca_once(builder, context.get_value_type(types.float64), size=n)
        array = make_array(array_type)(context, builder)
        intp = context.get_value_type(types.intp)
        populate_array(array, data=data, shape=[intp(n)], strides=[intp(8)], itemsize=intp(8), meminfo=None)
        return array._getvalue()

    return array_type(size), codegen


@intrinsic
def _llvm_sqrt(typingctx, x):
    if not isinstance(x, types.Float):
        return None

    def codegen(context, builder, signature, args):
        function = builder.module.declare_intrinsic("llvm.sqrt", [context.get_value_type(x)])
        return builder.call(function, args)

    return x(x), codegen


@njit(inline="always")
def sqrt(x):
    """The correctly rounded square root (nan for x < 0), as LLVM's intrinsic."""
    return _llvm_sqrt(float(x))


# the math module with sqrt as LLVM's intrinsic, for the sub-models compiled into the block loop
math_shim = pytypes.ModuleType("pdps_granular_contact.contact_block.math_shim")
for _name in dir(math):
    if not _name.startswith("_"):
        setattr(math_shim, _name, getattr(math, _name))
math_shim.sqrt = sqrt

_inlined = {}


def inline_part(function):
    """``function`` (a numba function) compiled again from its source, inlined where it is called,
    without errno or zero-divisor tests, the numba functions it calls likewise (module docstring)."""
    py_func = getattr(function, "py_func", function)
    if py_func in _inlined:
        return _inlined[py_func]
    scope = dict(py_func.__globals__)
    for name in py_func.__code__.co_names:
        value = scope.get(name)
        if value is math:
            scope[name] = math_shim
        elif value is math.sqrt:
            scope[name] = sqrt
        elif isinstance(value, CPUDispatcher) and value.py_func is not py_func:
            scope[name] = inline_part(value)
    rebuilt = pytypes.FunctionType(py_func.__code__, scope, py_func.__name__, py_func.__defaults__,
                                   py_func.__closure__)
    rebuilt.__module__ = py_func.__module__
    rebuilt.__qualname__ = py_func.__qualname__
    _inlined[py_func] = njit(inline="always", _nrt=False, error_model="numpy")(rebuilt)
    return _inlined[py_func]


@contextlib.contextmanager
def vectorized(width=4):
    """LLVM's loop vectorizer told to use ``width`` lanes for what numba compiles inside (module
    docstring); the cost model's own choice again after."""
    llvm.set_option("", f"-force-vector-width={width}")
    try:
        yield
    finally:
        llvm.set_option("", "-force-vector-width=0")
