"""spiral from Python: load a project, edit it, run spiral's analyses on it.

    import spiral
    p = spiral.load("scenarios/deepwater-fps.yaml")
    p.lines["L3"].segments[1].length += 2.0
    s = p.statics(offset=[10, 0, 0, 0, 0, 0])
    s.fairlead_tension_N            # numpy array, one value per line

Every analysis calls the design function of the CLI command of the same
name with the CLI's defaults and returns that command's JSON document
(docs/output-format.md) as a Result: a dict with the same keys, numbers in
numpy arrays. Errors raise InputError, SolverError or OutputError with the
CLI's messages. docs/python.md is the guide.
"""
import json
import os

from ._results import Result, to_python
from ._spiral import Error, InputError, OutputError, ProjectSession, SolverError

__all__ = ["load", "Project", "Result", "Error", "InputError", "SolverError", "OutputError"]


def load(path):
    """The project in ``path``, read and validated (InputError lists every
    problem with file:line:col, as ``spiral validate``)."""
    return Project(path)


class Segment:
    """One segment of a mooring line, as in ``mooring.lines[i].segments[j]``."""

    def __init__(self, session, line, index):
        self._session, self._line, self._index = session, line, index

    @property
    def length(self):
        """Unstretched length, m (the file's ``length``). Setting it edits the
        project in memory; it is validated when the project is next used."""
        return self._session.segment_length(self._line, self._index)

    @length.setter
    def length(self, length_m):
        self._session.set_segment_length(self._line, self._index, float(length_m))

    @property
    def type(self):
        """Name of the segment's ``line_types`` entry (editable, as ``length``)."""
        return self._session.segment_type(self._line, self._index)

    @type.setter
    def type(self, name):
        self._session.set_segment_type(self._line, self._index, str(name))

    def __repr__(self):
        return f"Segment(line={self._line!r}, index={self._index}, type={self.type!r}, length={self.length!r})"


class Line:
    """A mooring line: its name and its segments, from the anchor to the fairlead."""

    def __init__(self, session, name):
        self._session, self.name = session, name
        count = session.segment_count(name)
        self.segments = tuple(Segment(session, name, j) for j in range(count))

    @property
    def length(self):
        """Total unstretched length, m."""
        return sum(s.length for s in self.segments)

    def __repr__(self):
        return f"Line({self.name!r}, segments={list(self.segments)!r})"


class _Lines(dict):
    """The mooring lines by name, in project order."""

    def __missing__(self, name):
        raise KeyError(f"no mooring line named {name!r}; the lines: {', '.join(self)}")


class Project:
    """A project loaded from a file and perhaps edited in memory since.

    Editable: ``lines[NAME].segments[j].length`` and ``.type``, and any
    value the file writes by its field path (``set``/``get``). Every
    analysis validates the project as it is (InputError with the position in
    the file where an edited value was written) and runs on it; ``save``
    writes it back as the file's own text with only the edited values
    changed."""

    def __init__(self, path):
        self._session = ProjectSession(os.fspath(path))
        self.lines = _Lines((name, Line(self._session, name)) for name in self._session.line_names())

    @property
    def name(self):
        return self._session.name

    @property
    def file(self):
        """The file as it was named to ``load`` (messages name it so)."""
        return self._session.file

    @property
    def depth_m(self):
        return self._session.depth_m

    @property
    def load_cases(self):
        """The load case names (with the load-case matrix expanded)."""
        return self._session.load_case_names()

    @property
    def risers(self):
        return self._session.riser_names()

    @property
    def line_types(self):
        return self._session.line_type_names()

    def get(self, path):
        """The value the file writes at ``path``, the field path as messages
        name it (``environments[1].waves.hs``, ``hull.mass``,
        ``line_types[0].breaking_load``), as written: a string. KeyError when
        the file gives no value of its own there (a default applies)."""
        try:
            return self._session.field(path)
        except InputError:
            raise
        except ValueError as e:
            raise KeyError(str(e)) from None

    def set(self, path, value):
        """Sets any value the file writes, by its field path (``get``): a number,
        a name or a bool. The edit is made where the file writes the value and
        the project is read again, so it gets the same reading and checks as a
        file (InputError with the position, at once for a value that does not
        read, at the next analysis for one that fails a check); ``save``
        writes it. KeyError when the file gives no value there to replace
        (write the key in the file first). Segment edits made through
        ``lines`` stay."""
        if isinstance(value, bool):
            scalar = "true" if value else "false"
        elif isinstance(value, (int, float)):
            scalar = repr(float(value)) if isinstance(value, float) else str(value)
        else:
            scalar = str(value)
        try:
            self._session.set_field(path, scalar)
        except InputError:
            raise
        except ValueError as e:  # no value of its own at that path
            raise KeyError(str(e)) from None

    def validate(self):
        """Validates the project as edited; raises InputError."""
        self._session.validate()

    def statics(self, offset=(0, 0, 0, 0, 0, 0)):
        """``spiral statics --json --offset x,y,z,rx,ry,rz``: every mooring line
        at a hull offset (x, y, z in m; rx, ry, rz in deg), ``spiral.statics``."""
        offset = [float(v) for v in offset]
        if len(offset) != 6:
            raise InputError(f"{self.file}: offset: expected 6 values (x, y, z m, rx, ry, rz deg), got {len(offset)}")
        return _document(self._session.statics(offset))

    def equilibrium(self, case=None, damaged=None):
        """``spiral equilibrium --json [--case NAME] [--damaged LINE]``: the
        coupled static equilibrium, ``spiral.static_case`` (``offset_6dof``,
        ``lines``, ``risers``, ...)."""
        return _document(self._session.static_case(case, damaged, False))

    def stiffness(self, case=None, damaged=None, full=False):
        """The line array's 6x6 stiffness K (N/m, N/rad, N m/m, N m/rad;
        ``stiffness_6x6``) at the equilibrium of ``case``, as a numpy array;
        ``full=True``: the whole document of ``spiral stiffness --json`` (with
        the finite-difference check of K)."""
        document = _document(self._session.static_case(case, damaged, True))
        return document if full else document["stiffness_6x6"]

    def soz(self, case=None, step_deg=5.0, model="fe", tolerance=0.1, search_limit=20.0, march_step=2.5,
            condition="normal", exclude=(), threads=0, check=True, still_water_only=False, extreme=False,
            duration=10800.0, seed=1, progress=None):
        """``spiral soz --json``: the riser safe operational zones
        (``spiral.soz``: ``directions_deg``, ``platform.allowable_offset_m``,
        ``platform.governing_criterion``, per riser the same) and the load
        cases' offset check. Options as the command's (``tolerance`` m,
        ``search_limit`` and ``march_step`` % of depth, ``duration`` s).
        ``progress(fraction)`` is called as the zone's directions are
        searched. A riser that fails at zero offset raises InputError (as the
        CLI's exit 2) with the document as ``error.result``."""
        document = _document(
            self._session.soz(case, float(step_deg), float(tolerance), float(search_limit), float(march_step),
                              condition, model, list(exclude), int(threads), bool(check), bool(still_water_only),
                              bool(extreme), float(duration), int(seed), progress))
        failing = [r for r in document["risers"] if r["fails_at_zero_offset"]]
        if failing:
            error = InputError("\n".join(
                f"{self.file}: riser '{r['name']}' fails its criteria at zero offset ({document['conditions']['name']}): "
                f"{r['zero_offset_governing_criterion']} utilization {r['zero_offset_utilization']:.3f} > 1 — it has "
                f"no safe zone; check its criteria (criteria.risers, risers[].criteria) or its design" for r in failing))
            error.result = document
            raise error
        return document

    def analyze(self, case, level="sc", duration=10800.0, step=0.5, seed=1, line_dynamics=False, progress=None):
        """``spiral analyze``: the time-domain analysis of ``case`` at ``level``
        (uncoupled, sc, sc-enhanced, coupled) for ``duration`` s, output every
        ``step`` s. The document of ``summary.json`` (``channels``, ``timing_s``,
        ...) with ``time_series``: the columns of ``time_series.csv`` by name,
        numpy arrays at full precision (``pandas.DataFrame(ts.time_series)``).
        ``progress(fraction)`` is called as the dynamics advance."""
        summary, series = self._session.analyze(case, level, float(duration), float(step), int(seed),
                                                bool(line_dynamics), progress)
        document = _document(summary)
        document["time_series"] = series
        return document

    def lines_under_motion(self, case, motion, lines=(), step=0.5, ramp=20.0, seed=None, waves=True,
                           progress=None):
        """``spiral lines``: every selected mooring line and riser (default: every
        intact one) as a dynamic FE line with the hull following ``motion``, in
        ``case``'s current and sea. ``motion`` is a motion file (str or path:
        docs/lines.md) or a pair ``(times, offsets)``: times (N,) in s and
        offsets (N, 6) of surge, sway, heave in m and roll, pitch, yaw in deg.
        The document of ``summary.json`` (``spiral.motion_lines``) with
        ``time_series``: the columns of ``time_series.csv`` as numpy arrays.
        ``progress(fraction)`` is called as the lines advance."""
        if isinstance(motion, (str, os.PathLike)):
            summary, series = self._session.lines(case, os.fspath(motion), None, None, list(lines), float(step),
                                                  float(ramp), seed, bool(waves), progress)
        else:
            times, offsets = motion
            summary, series = self._session.lines(case, None, times, offsets, list(lines), float(step), float(ramp),
                                                  seed, bool(waves), progress)
        document = _document(summary)
        document["time_series"] = series
        return document

    def optimize(self, objective=None, algorithm=None, damaged=None, cases=(), max_evaluations=None, threads=0,
                 level="static", duration=10800.0, seed=1, progress=None):
        """``spiral optimize --json``: the pretension optimization
        (``spiral.optimization``); None leaves the project's ``optimization``
        setting. The project is not changed: ``lines[i].top_segment_after_m``
        are the new top-segment lengths to set before ``save``.
        ``progress(fraction)``: evaluations over the evaluation cap."""
        return _document(
            self._session.optimize(objective, algorithm, damaged, list(cases), max_evaluations, int(threads), level,
                                   float(duration), int(seed), progress))

    def save(self, path):
        """Writes the project as edited to ``path``: the loaded file's text with
        only the edited values changed (comments, order and every other value
        as they were; relative file references rewritten for the new folder).
        Validates first (InputError); OutputError when an edit cannot be
        written in place or the file cannot be written."""
        self._session.save(os.fspath(path))

    def __repr__(self):
        return f"spiral.Project({self.file!r}: {self.name!r}, {len(self.lines)} lines, {len(self.risers)} risers)"


def _document(text):
    return to_python(json.loads(text))
