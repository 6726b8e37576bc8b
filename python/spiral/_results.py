"""spiral's results in Python: the JSON documents of docs/output-format.md as
dicts with the same keys, their numeric lists as numpy arrays."""
import numbers

import numpy as np


class Result(dict):
    """A result document: a dict with the keys of its JSON document
    (docs/output-format.md), every list of numbers a numpy array (a list of
    numbers and nulls: float with NaN for null; a list of rows of numbers:
    2-D). Keys read as attributes too (``s.hull_force_6dof``). Where the
    document has per-line rows (``lines``), a key of the rows that the
    document itself does not have reads as that column over the lines
    (``s.fairlead_tension_N``: one value per line, in project order); where
    it has a ``time_series`` (``analyze``), a column name reads as that
    series."""

    def __getattr__(self, key):
        if key in self:
            return self[key]
        rows = dict.get(self, "lines")
        if isinstance(rows, list) and rows and isinstance(rows[0], dict) and key in rows[0]:
            return self.column("lines", key)
        series = dict.get(self, "time_series")
        if isinstance(series, dict) and key in series:
            return series[key]
        raise AttributeError(f"no key {key!r} in this {dict.get(self, 'format', 'result')} document")

    def column(self, table, key):
        """``key`` of every row of the list ``table`` (``"lines"``, ``"risers"``), as an array."""
        return _array([row[key] for row in self[table]], keep_list=True)

    def channel(self, name):
        """The statistics of channel ``name`` (``analyze``: ``channels[i]`` whose ``name`` it is)."""
        for channel in self["channels"]:
            if channel["name"] == name:
                return channel
        raise KeyError(f"no channel {name!r}; the channels: {', '.join(c['name'] for c in self['channels'])}")


def _is_number(value):
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _array(items, keep_list=False):
    """``items`` as a numpy array when they are all numbers (or nulls among
    numbers), all bools, or all arrays of one shape; else the list itself
    (or with ``keep_list``, a numpy array of objects is not made either)."""
    if items and all(_is_number(v) or v is None for v in items) and any(_is_number(v) for v in items):
        if any(v is None for v in items):
            return np.array([np.nan if v is None else v for v in items], dtype=float)
        return np.array(items)
    if items and all(isinstance(v, bool) for v in items):
        return np.array(items, dtype=bool)
    if items and all(isinstance(v, np.ndarray) for v in items) and len({v.shape for v in items}) == 1:
        return np.stack(items)
    return items


def to_python(value):
    """A value of a parsed JSON document with its dicts as Result and its
    numeric lists as numpy arrays."""
    if isinstance(value, dict):
        return Result((k, to_python(v)) for k, v in value.items())
    if isinstance(value, list):
        return _array([to_python(v) for v in value])
    return value
