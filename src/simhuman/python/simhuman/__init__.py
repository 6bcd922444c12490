"""simhuman from Python: physically simulated humans that carry out Chain-of-Contacts plans.

    import simhuman
    scene = simhuman.load_scene("sit_demo")
    ep = simhuman.run(simhuman.plan(scene, "sit on the chair"))
    ep.body_point("pelvis")[:, 2]          # pelvis height per recorded frame, m

The C++ core lives in simhuman._native (pybind11); this package re-exports it and adds the
Gymnasium-style vector environment (simhuman.vector) and the walking policy in PyTorch
(simhuman.policy, imported on use so torch is only needed there).
"""

from simhuman._native import (  # noqa: F401  (re-exported API)
    BadInputError,
    ClarificationNeeded,
    Episode,
    Error,
    NotFoundError,
    Plan,
    Scene,
    UnavailableError,
    body_point_names,
    cli,
    clip_convert,
    clip_gait,
    eval,
    export_policy,
    load_plan,
    load_scene,
    plan,
    planner_names,
    run,
    scene_names,
    train,
    version,
)
from simhuman import spaces, vector  # noqa: F401

__all__ = [
    "BadInputError", "ClarificationNeeded", "Episode", "Error", "NotFoundError", "Plan", "Scene",
    "UnavailableError", "body_point_names", "cli", "clip_convert", "clip_gait", "eval",
    "export_policy", "load_plan", "load_scene", "plan", "planner_names", "run", "scene_names",
    "train", "version", "spaces", "vector",
]
