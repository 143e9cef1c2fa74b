"""Argument types checked against a function's annotations, so that a wrong type is a TypeError
naming the function, the argument and what it takes.

Without it a wrong type reaches the compiled module, whose pybind11 error lists every
parameter of the internal function as arg0, arg1, ... and leaves the user to find which one
was wrong. Only the kinds the public functions use are checked: numbers, text, paths,
booleans, mappings, sequences, arrays (anything numpy converts: arrays and nested lists),
the classes named. Whole numbers are also checked against the fixed-width integers the compiled
module holds them in (an InvalidInputError, a ValueError, naming the range).
"""

from __future__ import annotations

import collections.abc
import functools
import inspect
import numbers
import os
import typing
from typing import Any, Callable, TypeVar, Union

import numpy as np

from . import _wifislam

F = TypeVar("F", bound=Callable[..., Any])


def _takes(hint: Any, value: Any) -> bool:
    """Whether `value` is of the annotated kind (True for kinds not checked here)."""
    if hint is Any:
        return True
    if hint is np.ndarray:  # anything numpy takes as an array: an array, nested lists, ...
        return (hasattr(value, "__array__") or hasattr(value, "__array_interface__")
                or (isinstance(value, collections.abc.Sequence)
                    and not isinstance(value, (str, bytes))))
    origin = typing.get_origin(hint)
    if origin is Union:
        return any(_takes(member, value) for member in typing.get_args(hint))
    if hint is type(None):
        return value is None
    if hint is bool:
        return isinstance(value, (bool, np.bool_))
    if hint is int:
        return isinstance(value, numbers.Integral) and not isinstance(value, bool)
    if hint is float:
        return isinstance(value, numbers.Real) and not isinstance(value, bool)
    if hint in (str, bytes):
        return isinstance(value, hint)
    if origin is os.PathLike or hint is os.PathLike:
        return isinstance(value, os.PathLike)
    # typing.get_origin gives collections.abc's classes for typing's generic aliases.
    if (origin or hint) in (collections.abc.Mapping, dict):
        # What dict() takes as a mapping: anything with keys() (a pandas row, say).
        return isinstance(value, collections.abc.Mapping) or hasattr(value, "keys")
    if (origin or hint) in (collections.abc.Sequence, list, tuple):
        return isinstance(value, collections.abc.Sequence) and not isinstance(value, (str, bytes))
    if isinstance(hint, type):
        return isinstance(value, hint)
    return True


def _kind(hint: Any) -> str:
    """The annotated kind in words ("a number or None")."""
    if typing.get_origin(hint) is Union:
        members = typing.get_args(hint)
        takes_paths = any(m is os.PathLike or typing.get_origin(m) is os.PathLike for m in members)
        words = []
        for member in members:
            # A path's str and bytes are said once, with os.PathLike.
            word = _kind(os.PathLike if takes_paths and member in (str, bytes) else member)
            if word not in words:
                words.append(word)
        return " or ".join(words)
    if hint is type(None):
        return "None"
    if hint is bool:
        return "True or False"
    if hint is int:
        return "a whole number"
    if hint is float:
        return "a number"
    if hint is str:
        return "text (str)"
    if hint is np.ndarray:
        return "an array"
    if hint is bytes or hint is os.PathLike or typing.get_origin(hint) is os.PathLike:
        return "a path (str, bytes or os.PathLike)"
    origin = typing.get_origin(hint) or hint
    if origin in (collections.abc.Mapping, dict):
        return "a dict"
    if origin in (collections.abc.Sequence, list, tuple):
        return "a sequence"
    return f"a {getattr(hint, '__name__', str(hint))}"


# Whole numbers the compiled module holds in fixed-width integers, by parameter name: outside,
# pybind11 would refuse with its list of the internal function's arguments. max_frames also
# refuses what the command line refuses (0 and negatives other than -1, "no limit").
_WHOLE_NUMBER_RANGES = {
    "seed": (0, 2**64 - 1, "a whole number from 0 to 2**64 - 1"),
    "max_frames": (1, 2**63 - 1, "-1 (the whole route) or a whole number of 1 or more"),
    "threads": (0, 2**31 - 1, "0 (every core) or a number of threads below 2**31"),
    "frame_index": (0, 2**63 - 1, "a whole number from 0 to 2**63 - 1"),
}
_INT32 = (-2**31, 2**31 - 1, "a whole number from -2**31 to 2**31 - 1")


def _out_of_range(parameter: str, hint: Any, value: Any) -> str:
    """What `parameter` takes, when `value` is a whole number outside it; "" otherwise."""
    if not isinstance(value, numbers.Integral) or isinstance(value, (bool, np.bool_)):
        return ""
    if not _takes(hint, value):
        return ""
    if not _takes_whole_numbers(hint):
        # A float parameter given an int: one beyond a double's range (10**400) reached
        # pybind11, whose TypeError listed the binding's own signatures.
        try:
            float(value)
        except OverflowError:
            return "a number within a float's range (below 1.8e308 in magnitude)"
        return ""
    low, high, words = _WHOLE_NUMBER_RANGES.get(parameter, _INT32)
    number = int(value)
    if parameter == "max_frames" and number == -1:
        return ""
    return "" if low <= number <= high else words


def _takes_whole_numbers(hint: Any) -> bool:
    if hint is int:
        return True
    if typing.get_origin(hint) is Union:
        return any(member is int for member in typing.get_args(hint))
    return False


def checked(function: F) -> F:
    """`function` with its arguments checked against its annotations on each call."""
    signature = inspect.signature(function)
    hints = typing.get_type_hints(function)
    name = function.__qualname__.replace(".__init__", "")

    @functools.wraps(function)
    def call(*args: Any, **kwargs: Any) -> Any:
        bound = signature.bind(*args, **kwargs)
        for parameter, value in bound.arguments.items():
            hint = hints.get(parameter)
            if hint is None:
                continue
            kind = signature.parameters[parameter].kind
            values = value if kind is inspect.Parameter.VAR_POSITIONAL else (value,)
            for each in values:
                if not _takes(hint, each):
                    shown = repr(each)
                    if len(shown) > 40:
                        shown = shown[:37] + "..."
                    raise TypeError(f"{name}(): {parameter} takes {_kind(hint)}, "
                                    f"got {type(each).__name__} {shown}")
                words = _out_of_range(parameter, hint, each)
                if words:
                    shown = str(int(each))
                    if len(shown) > 40:
                        shown = f"{shown[:20]}... ({len(shown)} digits)"
                    raise _wifislam.InvalidInputError(
                        f"{name}(): {parameter} takes {words}, got {shown}")
        return function(*args, **kwargs)

    return typing.cast(F, call)
