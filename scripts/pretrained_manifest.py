#!/usr/bin/env python3
"""Writes pretrained/manifest.json from run files produced by `vsr evolve` / `vsr finetune`.

For each run file given as `FILE=COMMAND` (the exact command that produced it), it records the
configuration, the best individual's training fitness, and the velocities that
`vsr validate --json` prints for it, so tests/pretrained.rs can check that it replays.
Usage: scripts/pretrained_manifest.py VSR_BINARY 'file.json=vsr evolve ...' ...
"""
import json
import pathlib
import subprocess
import sys

root = pathlib.Path(__file__).resolve().parent.parent / "pretrained"
vsr = sys.argv[1]
modules = []
for arg in sys.argv[2:]:
    name, command = arg.split("=", 1)
    run = json.loads((root / name).read_text())
    out = subprocess.run([vsr, "validate", "--genome", str(root / name), "--json"],
                         check=True, capture_output=True, text=True).stdout
    validation = json.loads(out)
    modules.append({
        "file": name,
        "command": command,
        "seed": run["config"]["seed"],
        "shape": run["best"]["shape"],
        "controller": run["best"]["controller"],
        "evaluations": run["generations"][-1]["evaluations"],
        "training_best": run["best"]["fitness"],
        "validation": [t["velocity"] for t in validation["terrains"]],
        "validation_median": validation["median"],
        "wall_seconds": (run.get("timing") or {}).get("wall_seconds"),
    })
manifest = {"format": "vsr-pretrained", "version": 1, "modules": modules}
(root / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
print(f"wrote {len(modules)} modules to {root / 'manifest.json'}")
