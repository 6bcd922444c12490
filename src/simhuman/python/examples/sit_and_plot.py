#!/usr/bin/env python3
"""The README's example: "sit on the chair", then plot the pelvis height (writes pelvis.png)."""
import matplotlib; matplotlib.use("Agg")  # noqa: E702  (no display needed)
import matplotlib.pyplot as plt
import simhuman

scene = simhuman.load_scene("sit_demo")
episode = simhuman.run(simhuman.plan(scene, "sit on the chair"), seed=1)
print(episode.result["success"], episode.result["end_reason"])
plt.plot(episode.time_s, episode.body_point("pelvis")[:, 2])
plt.xlabel("time (s)"); plt.ylabel("pelvis height (m)")  # noqa: E702
plt.savefig("pelvis.png")
