"""ivv: verification and validation of impact contact models, from Python.

The functions mirror the command line and return what its libraries compute:

    >>> import ivv
    >>> s = ivv.scene("paper", v0=1, zeta=0.1)
    >>> r = ivv.simulate(s)
    >>> r.e, r.F_max, r.model_choice["route"]
    >>> cols = ivv.sweep(s, v0=np.geomspace(0.1, 10, 50), zeta=[0, 0.1], threads=0)
    >>> verdict = ivv.check_law(force="K_h*z^1.5")

scene()      a shipped scene or a TOML file, with overrides; derived parameters as attributes
simulate()   one impact: the fields of `ivv simulate --json` (and the trajectory as numpy arrays)
sweep()      a v0 x zeta (x scene values) grid in parallel: numpy columns, those of `ivv sweep`'s CSV
check_law()  a contact law through the conformance checks: `ivv check-law --json`
calibrate()  a law's parameters fitted to measured restitution: `ivv calibrate --json`
predict()    e with its 95 % band, or the V&V 20 comparison: `ivv predict --json`

Bad input raises InputError (a ValueError) with the command line's message; a computation that
fails is a result whose status and reason say why, not an exception. Numbers the CLI's JSON
prints as null because they are not finite (t_contact of a captured impact, zeta without a
yield strength) are nan or inf here.
"""

import os as _os

import numpy as _np

from . import _ivv
from ._ivv import InputError

__version__ = _ivv.__version__

__all__ = ["InputError", "Scene", "SimulationResult", "LawVerdict", "Calibration", "Prediction",
           "scene", "simulate", "sweep", "check_law", "calibrate", "predict", "data_directories",
           "scene_values"]


def _register_data_directories():
    """Finds the shipped scenes beside this package: <build>/share/ivv in a build tree
    (<build>/python/ivv), <prefix>/share/ivv once installed (<prefix>/lib/pythonX.Y/...)."""
    here = _os.path.dirname(_os.path.abspath(__file__))
    for up in (2, 4):
        candidate = _os.path.join(here, *([_os.pardir] * up), "share", "ivv")
        if _os.path.isdir(_os.path.join(candidate, "scenes")):
            _ivv._add_data_directory(_os.path.normpath(candidate))


_register_data_directories()


def data_directories():
    """The directories searched for shipped scenes and tables, in order ($IVV_DATA_DIR first)."""
    return _ivv._data_directories()


class _Fields:
    """Attribute access to the entries of a dict (the CLI's JSON as Python objects)."""

    def __getattr__(self, name):
        for fields in self._lookup():
            if isinstance(fields, dict) and name in fields:
                return fields[name]
        raise AttributeError(f"{type(self).__name__} has no field '{name}'")

    def __dir__(self):
        names = set(super().__dir__())
        for fields in self._lookup():
            if isinstance(fields, dict):
                names.update(fields)
        return sorted(names)


class Scene(_Fields):
    """A scene (docs/design.md §5) with its overrides applied and its derived parameters.

    Every key of `ivv scene show --json` is an attribute: E_star, K_h, z_y, K_y, omega0, zeta,
    c, v_yield, zener_lambda, ... (SI units). to_dict() gives them all.
    """

    def __init__(self, compiled):
        self._scene = compiled
        self._dict = compiled.to_dict()

    def _lookup(self):
        return (self._dict,)

    def to_dict(self):
        """The scene and its derived parameters, as `ivv scene show --json` prints them."""
        return dict(self._dict)

    def __repr__(self):
        d = self._dict
        return (f"<ivv.Scene {d.get('name')!r} from {self._scene.source!r}: v0={d.get('v0')} m/s, "
                f"zeta={d.get('zeta')}, c={d.get('c')} N s/m>")


def scene(name_or_path="paper", **overrides):
    """A scene: a shipped name ("paper", "paper-damped", "chung-ooi-1-glass", ...) or a TOML file.

    Overrides (SI units), as the command line's flags:
      v0            impact velocity [m/s]                         (--v0)
      zeta          damping ratio of the series dashpot [-]       (--zeta)
      c             dashpot coefficient [N s/m]                   (--c)
      lambda_       Zener's lambda: the dashpot giving it at v0   (--lambda)
      no_dashpot    True: drop the scene's dashpot                (--no-dashpot)
    and every scene value by its key with an underscore for the dot (scene_values() lists
    them with their units): impactor_mass (or mass), impactor_radius (or radius),
    impactor_youngs_modulus, impactor_poisson_ratio, target_youngs_modulus,
    target_poisson_ratio, target_yield_strength (or yield_strength), target_shear_strength,
    target_radius, target_mass; for a scene whose dashpot comes from its [structure]:
    structure_thickness, structure_density, structure_area, structure_bending_stiffness,
    structure_youngs_modulus, structure_poisson_ratio, and a finite plate's structure_length_x,
    structure_length_y, structure_impact_x, structure_impact_y, structure_D11 ... D66.
    None leaves an optional value out (a yield strength, a structure's own E, nu or D*).

    Returns a Scene whose attributes are the derived parameters (E_star, K_h, z_y, K_y, zeta,
    c, v_yield, ...). Raises InputError naming the field and the accepted range.

    >>> ivv.scene("paper", v0=2, zeta=0.1).c
    """
    if isinstance(name_or_path, Scene):
        raise TypeError("scene() takes a name or a path; this is already a Scene")
    return Scene(_ivv._load_scene(_os.fspath(name_or_path), overrides))


def _as_scene(s):
    if isinstance(s, Scene):
        return s
    if isinstance(s, (str, _os.PathLike)):
        return scene(s)
    raise TypeError(f"expected an ivv.Scene or a scene name/path, got {type(s).__name__}")


def _model_options(law, integrator, model, rtol, atol, dt, max_steps, params, force, unload,
                   allow_tension, hc_k, hc_mu):
    """The law (default "elastoplastic"; or the expression law of force/unload), integrator and
    tolerances as keywords of the compiled module; law and force together are refused, as the
    command line refuses --law with --force."""
    if law is not None and force is not None:
        raise TypeError("give law (a built-in law) or force (an expression law), not both")
    opts = dict(integrator=integrator, model=model, rtol=rtol, atol=atol, dt=dt,
                max_steps=max_steps, params=params, force=force, unload=unload,
                allow_tension=allow_tension, hc_k=hc_k, hc_mu=hc_mu)
    if law is not None:
        opts["law"] = law
    return opts


class SimulationResult(_Fields):
    """One impact: the content of `ivv simulate --json`.

    Attributes are the keys of its "result" (status, reason, failure, e, e_poisson,
    e_energetic, F_max, t_contact, z_max, alpha_max, z_perm, separated, energy, steps, ...),
    then the top-level ones (scene, request, law, model_choice). ok is True when the run
    separated or was captured. On a finite plate (a scene with [structure] length_x, length_y)
    they are those of its JSON: e, e_first, contacts, mode_count, ..., regime and model_choice
    (the model the impact needs, every cheaper model measured against the full plate). trajectory is None, or (simulate(trajectory=True)) a dict of
    numpy arrays t, alpha, alpha_dot, y, z, F, tau, alpha_bar, F_bar.
    """

    def __init__(self, json_dict, trajectory):
        self._dict = json_dict
        self.trajectory = trajectory

    def _lookup(self):
        return (self._dict.get("result"), self._dict)

    @property
    def ok(self):
        """True when the impact separated or was captured (the CLI exits 0)."""
        r = self._dict["result"]
        if "status" not in r:  # a finite plate: ok, or the reason it failed
            return bool(r.get("ok"))
        return r["status"] in ("separated", "captured")

    @property
    def model_choice(self):
        """What ran and why (route, integrator, reasons, estimated error), or None."""
        return self._dict.get("model_choice")

    def to_dict(self):
        """The object `ivv simulate --json` prints (non-finite numbers as nan/inf)."""
        return self._dict

    def __repr__(self):
        r = self._dict["result"]
        status = r.get("status", "ok" if r.get("ok") else "failed")
        return f"<ivv.SimulationResult {status}: e={r.get('e')} F_max={r.get('F_max')}>"


def simulate(scene, law=None, integrator="auto", model="auto", rtol=None,
             trajectory=False, *, atol=None, dt=None, max_steps=None, params=None, force=None,
             unload=None, allow_tension=False, hc_k=None, hc_mu=None, model_tol=None):
    """One impact, as `ivv simulate --json` computes it.

    scene       an ivv.Scene, or a name/path (then ivv.scene(name))
    law         "hertz", "elastoplastic" (the default), "linearized", "hunt-crossley"
    integrator  "auto" (dop853 or rodas4 by stiffness) or a name of `ivv integrators`
    model       "auto": exact closed forms where they exist; "full": always integrate; a
                finite plate also takes "half-space", "infinite-plate", "quasi-static"
    model_tol   a finite plate: the tolerance of its choice of model (default 1e-3)
    rtol, atol  tolerances (default 1e-10, 1e-12); dt: rk4's normalised step
    params      {name: value} of the law (--param); hc_k, hc_mu: Hunt-Crossley's K and mu
    force, unload, allow_tension  an expression law instead of `law` (--force, --unload)
    trajectory  True: result.trajectory holds numpy arrays (t, alpha, alpha_dot, y, z, F, ...)

    Returns a SimulationResult (r.e, r.F_max, r.t_contact, r.energy, r.model_choice, ...). A
    failed computation is a result with status, reason and failure; bad input raises
    InputError with the CLI's message.
    """
    s = _as_scene(scene)
    opts = _model_options(law, integrator, model, rtol, atol,
                          dt, max_steps, params, force, unload, allow_tension, hc_k, hc_mu)
    if model_tol is not None:
        opts["model_tol"] = model_tol
    json_dict, traj = _ivv._simulate(s._scene, opts, bool(trajectory))
    return SimulationResult(json_dict, traj)


_TEXT_COLUMNS = ("route", "integrator", "status", "reason")


def scene_values():
    """The scene values a sweep can vary, {key: unit}: the keys of `ivv sweep --set KEY=...`
    ("impactor.mass", "structure.thickness", ...), in SI units ("-": dimensionless)."""
    return dict(_ivv._scene_values())


def _axis_key(keyword):
    """A keyword of sweep() as the scene key it varies: structure_thickness ->
    structure.thickness (the section, then the key), and ivv.scene()'s mass, radius,
    yield_strength."""
    key = _ivv._scene_key(keyword)
    if not key:
        names = ", ".join(k.replace(".", "_", 1) for k in scene_values())
        raise TypeError(f"sweep() got an unexpected keyword argument '{keyword}' (the scene "
                        f"values it can sweep: {names})")
    return key


def sweep(scene, v0, zeta=None, threads=0, law=None, integrator="auto",
          model="auto", rtol=None, *, atol=None, dt=None, max_steps=None, params=None,
          force=None, unload=None, allow_tension=False, hc_k=None, hc_mu=None, **axes):
    """COR and peak force over a v0 x zeta grid (x any scene values), computed in parallel
    (`ivv sweep`).

    v0       impact velocities [m/s], array_like
    zeta     damping ratios, array_like (0: no dashpot); None: every point keeps the scene's
             own dashpot (its c, lambda or [structure]) and the zeta column is its derived zeta
    threads  worker threads (0: all cores)
    **axes   scene values swept too, as `ivv sweep --set KEY=...`: the key with its section
             and an underscore for the dot (structure_thickness=np.linspace(1e-3, 1e-2, 10),
             impactor_mass=[0.1, 0.5], target_yield_strength=...; also ivv.scene()'s mass,
             radius, yield_strength), each array_like in the key's unit (scene_values())
    and the law, integrator and tolerances as simulate() takes them.

    Returns a dict of numpy arrays, one per column of the sweep CSV, in grid order (row-major
    over v0, zeta, then the axes in the order given, the last fastest; without axes point i has
    v0[i // len(zeta)], zeta[i % len(zeta)]): v0, zeta, one column per axis named by its key
    ("structure.thickness"), e, e_poisson, e_energetic, F_max, t_F_max, t_contact, z_max,
    alpha_max, z_perm, energy_residual (float; nan for a failed point, where the CSV is empty),
    steps (int), route, integrator, status, reason (str). The C++ work runs with the GIL
    released; Ctrl-C stops it (KeyboardInterrupt) after the points in flight.
    """
    s = _as_scene(scene)
    v = _np.atleast_1d(_np.asarray(v0, dtype=float)).ravel()
    z = None if zeta is None else _np.atleast_1d(_np.asarray(zeta, dtype=float)).ravel()
    opts = _model_options(law, integrator, model, rtol, atol,
                          dt, max_steps, params, force, unload, allow_tension, hc_k, hc_mu)
    scene_axes = [(_axis_key(name), _np.atleast_1d(_np.asarray(values, dtype=float)).ravel())
                  for name, values in axes.items()]
    columns = _ivv._sweep(s._scene, v, z, int(threads), opts, scene_axes)
    for name in _TEXT_COLUMNS:
        columns[name] = _np.array(columns[name], dtype=str)
    return columns


class LawVerdict(_Fields):
    """A contact law's verdict with every check: the content of `ivv check-law --json`.

    Attributes are its keys: verdict ("pass" or "fail"), brief, checks (each with id, passed,
    measured, reference, tolerance, why, detail, ...), skipped (id and why), not_applicable,
    cor, law. passed is verdict == "pass"; failed() lists the ids of the checks that failed.
    """

    def __init__(self, json_dict):
        self._dict = json_dict

    def _lookup(self):
        return (self._dict,)

    @property
    def passed(self):
        """True when every check that ran passed (verdict "pass"; `ivv check-law` exits 0)."""
        return self._dict["verdict"] == "pass"

    def failed(self):
        """The ids of the checks that failed."""
        return [c["id"] for c in self._dict["checks"] if not c["passed"]]

    def to_dict(self):
        """The object `ivv check-law --json` prints (non-finite numbers as nan/inf)."""
        return self._dict

    def __repr__(self):
        return f"<ivv.LawVerdict {self._dict.get('verdict')}: failed {self.failed()}>"


def check_law(force=None, unload=None, params=None, *, law=None, scene="paper",
              allow_tension=False, onset_force=None, expect_cor=None, cor_tolerance=None,
              elastic_at_low_speed=False, monotone=True, cor_increasing_in_v0=False,
              captured_below=None, v0=None, zeta=None, c=None, name=None, integrator="auto",
              model="auto", rtol=None, atol=None, hc_k=None, hc_mu=None):
    """A contact law through the conformance checks (`ivv check-law --json`).

    force, unload   the loading and unloading force [N] as expressions in z, zdot, zmax, the
                    scene's m, R, E_star, K_h, z_y, K_y, v0 and the names of `params`
    law             a built-in law's name instead of an expression
    params          {name: value}; allow_tension: F may pull, contact ends at z = 0
    onset_force     an adhesive law's intended force at z = 0 on first loading [N], an
                    expression like force (e.g. "-Fad"; `--onset-force`): static.onset holds
                    F(0) to it instead of to 0
    scene           the scene (an ivv.Scene or a name/path; default "paper")
    Claims: expect_cor (an expression in v0, e.g. "hc_cor(...)"; captured rows are judged
    against their interval [0, e_bound]), cor_tolerance, elastic_at_low_speed, monotone (e
    falls with v0 and with damping; default True), cor_increasing_in_v0 (e never falls as v0
    rises, in place of monotone's claim in v0; `--cor-increasing-in-v0`), captured_below (a
    speed V [m/s]: captured at every grid velocity below V, and without a dashpot rebounding
    at every one at or above it; `--captured-below`).
    Grid: v0, zeta, c (array_like; default: the CLI's grid around the scene's v0).

    Returns a LawVerdict: .verdict, .passed, .checks (every check with its measured value,
    reference, tolerance and why), .skipped, .law.
    """
    s = _as_scene(scene)
    opts = _model_options(law, integrator, model, rtol, atol, None, None, params, force,
                          unload, allow_tension, hc_k, hc_mu)
    if params is None:
        del opts["params"]
    checks = dict(expect_cor=expect_cor, cor_tolerance=cor_tolerance,
                  elastic_at_low_speed=elastic_at_low_speed, monotone=monotone, name=name,
                  cor_increasing_in_v0=cor_increasing_in_v0, captured_below=captured_below,
                  onset_force=onset_force)
    for key, grid in (("v0", v0), ("zeta", zeta), ("c", c)):
        if grid is not None:
            checks[key] = [float(x) for x in _np.atleast_1d(_np.asarray(grid, dtype=float))]
    return LawVerdict(_ivv._check_law(s._scene, opts, checks))


def _data_options(data):
    """A path to a measured-data CSV, or columns {v0, e, u_e, F_max, ...} written as that CSV
    (every float with repr's digits, which read back exactly)."""
    if isinstance(data, (str, _os.PathLike)):
        return {"data": _os.fspath(data)}
    if not isinstance(data, dict):
        raise TypeError("data: a path to a CSV, or a dict of columns (v0, e, u_e, ...)")
    names = list(data)
    columns = [_np.atleast_1d(_np.asarray(data[n], dtype=float)) for n in names]
    lines = [",".join(names)]
    for row in zip(*columns):
        lines.append(",".join("" if _np.isnan(x) else repr(float(x)) for x in row))
    return {"data_text": "\n".join(lines) + "\n"}


class Calibration(_Fields):
    """A calibration: the content of `ivv calibrate --json` (the file `ivv predict` reads).

    Attributes are its keys: fit (per fitted parameter: name, unit, value, standard_error,
    lower95, upper95, profile95, identifiable, ...), chi2, dof, p_value, covariance,
    correlation, residuals, law, parameters (the law's), scene, ...
    ok is False when the fit failed (failure says why; then there are no fields). brief is the
    summary the CLI prints. save(path) writes the JSON that `ivv predict --calibration` reads.
    """

    def __init__(self, out):
        self.ok = out["ok"]
        self.failure = out["failure"]
        self.brief = out["brief"]
        self._text = out["json"]
        self._dict = None if self._text is None else __import__("json").loads(self._text)

    def _lookup(self):
        return (self._dict,)

    def to_dict(self):
        """The object `ivv calibrate --json` prints (None when the fit failed)."""
        return self._dict

    def save(self, path):
        """Writes the calibration JSON (as `ivv calibrate --out FILE`)."""
        if self._text is None:
            raise ValueError(f"the calibration failed: {self.failure}")
        with open(path, "w") as f:
            f.write(__import__("json").dumps(self._dict, indent=2) + "\n")

    def __repr__(self):
        if not self.ok:
            return f"<ivv.Calibration failed: {self.failure}>"
        fitted = ", ".join(f"{p['name']}={p['value']:.6g}" for p in self._dict["fit"])
        return f"<ivv.Calibration {self._dict.get('law')}: {fitted}>"


def calibrate(scene, data, fit, law=None, *, start=None, bounds=None, scan=False,
              profile=True, threads=0, integrator="auto", model="auto", params=None,
              force=None, unload=None, allow_tension=False):
    """A law's parameters fitted to measured restitution (`ivv calibrate --json`).

    scene    an ivv.Scene or a name/path (e.g. "paper-damped"); its values are the starts
    data     a measured-data CSV (v0, e, optional u_e, F_max, t_contact and their u_), or a
             dict of those columns as arrays
    fit      the parameters to fit, e.g. ["c", "yield_strength"] (a comma string also works)
    start    {name: value} start values; bounds {name: (lo, hi)}; scan: coarse scan for the
             start; profile: profile-likelihood intervals (default True)
    law, force, unload, params  the law, as simulate() takes it

    Returns a Calibration (.fit, .chi2, .p_value, .covariance, ..., .save(path)); a fit
    that fails is a Calibration with ok False and its failure. Bad input raises InputError.
    """
    s = _as_scene(scene)
    if isinstance(fit, str):
        fit = [name for name in fit.split(",") if name]
    opts = _model_options(law, integrator, model, None, None,
                          None, None, params, force, unload, allow_tension, None, None)
    fit_options = dict(fit=list(fit), start=start, scan=scan, profile=profile,
                       threads=int(threads), **_data_options(data))
    if bounds is not None:
        fit_options["bounds"] = {k: (float(lo), float(hi)) for k, (lo, hi) in bounds.items()}
    return Calibration(_ivv._calibrate(s._scene, opts, fit_options))


class Prediction(_Fields):
    """A prediction: the content of `ivv predict --json`.

    band is the list of points (v0, e, e_lo95, e_hi95, u_input, u_num); columns() gives them
    as numpy arrays. Against held-back data, vv20 holds the ASME V&V 20 comparison per point
    (S, D, E, u_val, exceeds_2u_val, ...) and exceeding the count beyond 2 u_val. ok is False
    when a draw failed (failure says which).
    """

    def __init__(self, out):
        self.ok = out["ok"]
        self.failure = out["failure"]
        self._dict = out["json"]

    def _lookup(self):
        return (self._dict,)

    def columns(self, part="band"):
        """The points of `band` (or "vv20") as a dict of numpy arrays."""
        points = self._dict.get(part) or []
        return {k: _np.array([p[k] for p in points]) for k in (points[0] if points else {})}

    def to_dict(self):
        """The object `ivv predict --json` prints."""
        return self._dict


def predict(calibration, v0=None, data=None, *, samples=10000, seed=1, threads=0):
    """e with its 95 % band from a calibration, or its ASME V&V 20 comparison with held-back
    data (`ivv predict --json`).

    calibration  a Calibration (ivv.calibrate) or the path of its JSON file
    v0           speeds [m/s] of the band, array_like; or
    data         held-back measurements (a CSV path or a dict of columns, as for calibrate)
    samples      Monte Carlo draws over the fitted covariance (default 10000); seed (default 1)

    Returns a Prediction (.band, .columns(), .vv20, .exceeding).
    """
    if isinstance(calibration, Calibration):
        if calibration._text is None:
            raise ValueError(f"the calibration failed: {calibration.failure}")
        options = {"calibration_text": calibration._text}
    else:
        options = {"calibration": _os.fspath(calibration)}
    options.update(samples=int(samples), seed=int(seed), threads=int(threads))
    if v0 is not None:
        options["v0"] = [float(x) for x in _np.atleast_1d(_np.asarray(v0, dtype=float))]
    if data is not None:
        options.update(_data_options(data))
    return Prediction(_ivv._predict(options))
