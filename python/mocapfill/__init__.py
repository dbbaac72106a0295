"""mocapfill: motion capture conversion, retargeting, filtering and sketch filling.

    import mocapfill
    sketch = mocapfill.load("sketch.glb")
    db = mocapfill.Database.open("default")          # or an .mfdb file, or motion folders
    out, report = mocapfill.fill(sketch, db, method="hierarchical")
    mocapfill.save(out, "filled.glb")
    print(report["key_error_max_deg"])

Clips are numpy arrays: ``scene.clip(0).rotations`` is (frames, joints, 4) local unit
quaternions (x, y, z, w), ``.translations`` (frames, joints, 3) metres, ``.times`` seconds.
Every failure raises a subclass of ``mocapfill.Error`` whose ``exit_code`` is the one the
command-line tool exits with (1 usage, 2 input, 3 processing, 4 output).
"""
import json

from ._mocapfill import (  # noqa: F401
    Clip,
    Database,
    Error,
    InputError,
    OutputError,
    PcaModel,
    ProcessingError,
    Scene,
    UsageError,
    __version__,
    convert,
    default_database_path,
    describe_pipeline,
    filter,
    load,
    pipeline_node_types,
    retarget,
    save,
)
from ._mocapfill import _fill, _FillOptions, _run_pipeline


def _option_text(value):
    """A keyword argument as the fill's option text: true/false, comma lists, key=value maps."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, dict):
        return ",".join("%s=%s" % (k, _option_text(v)) for k, v in value.items())
    if isinstance(value, (list, tuple)):
        return ",".join(_option_text(v) for v in value)
    return str(value)


def fill(sketch, database, method="hierarchical", map=None, rest="auto", rate_hz=0.0, keep=None,
         synthesize=None, position_keys=None, feet="plant", texture=True, coverage="blend", pca=None,
         threads=0, **options):
    """Fills the sketch's missing joints from ``database``; returns ``(scene, report)``.

    The sketch's keyed joints (those with ``rotation_keys``) are kept at their keys; every
    other mapped joint is synthesised. ``report`` is the dict ``mocapfill fill --report``
    writes (key errors at the sketch's exact key times, fragment sources, coverage, timings).
    ``database`` may be a Database or anything Database.open takes. Any other option of the
    fill by its pipeline name (``mocapfill.pipeline_node_types()``, node type fill), e.g.
    ``candidates=64``, ``coverage_poor=0.06``, ``dial={1: 1.5}``, ``gains=[1, 1, 1.5]``,
    checked as the command line checks its flags.
    """
    if not isinstance(database, Database):
        database = Database.open([database] if isinstance(database, str) else list(database))
    if feet not in ("plant", "free"):
        raise UsageError("feet: expected 'plant' or 'free', got %r" % (feet,))
    more = {name: _option_text(value) for name, value in options.items()}
    options = _FillOptions()
    options.more = more
    options.method = method
    options.map = dict(map or {})
    options.rest = rest
    options.output_rate_hz = float(rate_hz)
    options.keep = list(keep or [])
    options.synthesize = list(synthesize or [])
    options.position_keys = list(position_keys or [])
    options.plant_feet = feet == "plant"
    options.texture = bool(texture)
    options.coverage = coverage
    options.threads = int(threads)
    if pca is not None:
        options.pca_model = pca if isinstance(pca, PcaModel) else PcaModel.open(pca)
    scene, report = _fill(sketch, database, options)
    return scene, json.loads(report)


def _open(paths=None, **options):
    """Database.open(path or list of paths; None or "default" = the default database)."""
    if paths is None:
        paths = []
    elif isinstance(paths, str):
        paths = [paths]
    return Database._open(list(paths), **options)


Database._open = Database.open
Database.open = staticmethod(_open)
Database.default = staticmethod(lambda progress=None: _open(None, progress=progress))

__all__ = ["Clip", "Database", "Error", "InputError", "OutputError", "PcaModel", "ProcessingError", "Scene",
           "UsageError", "convert", "default_database_path", "describe_pipeline", "fill", "filter", "load",
           "pipeline_node_types", "retarget", "run_pipeline", "save", "__version__"]


def run_pipeline(path, sets=None):
    """Runs a pipeline file (docs/pipeline.md) as ``mocapfill run`` does; returns the run report
    (a dict: per-node seconds and warnings, each fill node's report). ``sets`` overrides options:
    ``["out.path=/tmp/x.glb", "fill.method=fragment"]``. Its export nodes write their files."""
    report, _warnings = _run_pipeline(path, list(sets or []))
    return json.loads(report)
