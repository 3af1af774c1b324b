"""A body search of one's own around a frozen pretrained attention module (docs/python.md):
a (1 + 8) search over bodies from a 3 x 3 box; each child adds or removes one voxel, brings
fresh genes for its voxels, keeps the module's 32-gene attention block and bias; the core's
shape check (param_count) refuses bodies in pieces. `vsr codesign` does this properly (a
gallery of bodies, genes that follow voxels); this shows the Python pieces."""
import numpy as np
import vsr

module = vsr.load_run("pretrained/biped-4x3-attention.json")["best"]["genome"]
rng = np.random.default_rng(1)


def rows(cells):  # a set of (x, y) cells -> the rows notation, top row first
    xs, ys = [x for x, _ in cells], [y for _, y in cells]
    return "-".join("".join("1" if (x, y) in cells else "0" for x in range(min(xs), max(xs) + 1))
                    for y in range(max(ys), min(ys) - 1, -1))


def child(cells):
    while True:
        x, y = sorted(cells)[rng.integers(len(cells))]
        dx, dy = [(1, 0), (-1, 0), (0, 1), (0, -1)][rng.integers(4)]
        new = cells - {(x, y)} if rng.random() < 0.3 else cells | {(x + dx, y + dy)}
        try:
            if 4 <= len(new) <= 20 and vsr.param_count(rows(new), "attention"):
                genes = rng.uniform(-1, 1, 4 * len(new))
                return new, np.concatenate([module[:32], genes, module[-1:]]).astype(np.float32)
        except ValueError:  # in pieces: the core refuses it
            pass


best = {(x, y) for x in range(3) for y in range(3)}
best_speed = -np.inf
for generation in range(5):
    children = [child(best) for _ in range(8)]
    speeds = vsr.evaluate_bodies([rows(c) for c, _ in children], [g for _, g in children],
                                 "attention", f"hilly-1-10-{generation}", seconds=10.0)
    i = int(np.argmax(speeds))
    if speeds[i] > best_speed:
        best, best_speed = children[i][0], speeds[i]
    print(f"generation {generation}: best {rows(best)} at {best_speed:.3f} m/s")
