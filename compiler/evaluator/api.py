"""`evaluate`: run one function of a GLSL module over numpy arrays at a chosen precision."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from glint.compiler.evaluator.interpreter import Interpreter
from glint.compiler.evaluator.values import AnyValue, lanes, to_numpy

FLOAT_DTYPES = (np.float16, np.float32, np.float64)


def evaluate(
    source: str,
    function: str,
    args: dict[str, Any] | Sequence[Any],
    dtype: Any = np.float32,
    predefined: dict[str, str] | None = None,
    filename: str = "<input>",
    externals: dict[str, Any] | None = None,
    external_types: Mapping[str, str] | None = None,
) -> Any:
    """Call `function` of `source` with `args` (by parameter name or position), vectorised.
    `externals` give what the source uses and does not define (values or functions),
    `external_types` their GLSL types where the source does not declare them.

    A float is an array of lanes (any shape); a vecK an array (..., K) or a sequence of K lane
    arrays; a struct a dict of its fields. The result comes back the same way, broadcast to
    the lanes of the arguments. A function with out/inout parameters returns
    `(result, {name: value})`, or just the dict when it returns void.
    """
    if np.dtype(dtype).type not in FLOAT_DTYPES:
        raise ValueError(f"dtype must be float16, float32 or float64, not {dtype}")
    module = Interpreter(source, filename, predefined, dtype, externals, external_types)
    fn = module.functions.get(function)
    if not fn:
        raise KeyError(f"{filename}: no function '{function}'")
    if isinstance(args, dict):
        converted: dict[str, Any] | list[Any] = dict(args)
    else:
        converted = list(args)
    result, outs = module.call(function, converted)
    shape = _lane_shape([*outs.values(), result], module, fn[0].params, args)
    value = None if fn[0].return_type == "void" else to_numpy(result, shape)
    if not outs:
        return value
    outputs = {k: to_numpy(v, shape) for k, v in outs.items()}
    return outputs if value is None else (value, outputs)


def _lane_shape(
    values: list[AnyValue], module: Interpreter, params: Any, args: Any
) -> tuple[int, ...]:
    """The lanes of the arguments, so that uniform results come back one per lane."""
    items = args.values() if isinstance(args, dict) else args
    shapes = []
    for (_, type_, _), arg in zip(params, items, strict=False):
        shapes.append(lanes(module.from_python(arg, type_)))
    return np.broadcast_shapes(*shapes) if shapes else ()
