#!/usr/bin/env python3
"""One bond-breaking pass from a state, as the published code and as the package make it, and
what the contact number z of that state is made of.

    breaking.py DATA [DATA ...] [--passes 20000] [--seed 1]

DATA: a package data file with adhesive bonds (bond type 2), segment bonds (type 1) and the
Vertices section (d_sigma first), e.g. growth_step/published_frame_1.data or a frame that
run.py --work DIR keeps (DIR/frame_K.data). For each file it prints

* z = 2 (neighbour cell pairs)/cells, the pairs split into bonded ones and contact-only ones (a
  vertex pair closer than (sigma_i + sigma_j)/2 and no adhesive bond), as compute dpoly/tissue
  counts them;
* the breaking candidates: stretched bonds (r > s), those at a junction edge (a ring neighbour
  of either end has no adhesive bond), the largest r/s against r*/s = 1 + sqrt 2;
* the mean number of bonds one pass breaks, over --passes passes with independent draws, and
  the mean number of cell pairs that lose their last bond, for two loops over the same law
  p = exp(-beta dU / z_mn), dU = 1 - (r/s - 1)^2/2, z_mn = (z_m + z_n)/2 + 1 (z: adhesive bonds
  of a cell), sure break for dU < 0, stochastic ones only at junction edges:
  - published: meso2D::updateMesophyllBondNetwork(), cell pairs m < n, their vertices in ring
    order, z_mn computed once per cell pair before its vertex loop, a draw for every stretched
    bond that does not break for sure;
  - package: fix mesophyll/break, bonds in the order of their atom IDs, z_mn from the counts as
    they are at each bond (bonds broken earlier in the pass count).
beta = 100 and h = 1 as the default set (README.md, parameter mapping). Needs python3-numpy.
"""
import argparse
import collections
import math
import random

import numpy as np

BETA = 100.0
SECTIONS = {"Masses", "Atoms", "Velocities", "Bonds", "Angles", "Vertices", "Stiffness"}


class State:
    """Positions, sigma, rings and adhesive bonds of a data file (indices 0..n-1 by atom ID)."""

    def __init__(self, path):
        atoms, segments, adhesive, sigma, box, section = {}, [], [], {}, {}, None
        for line in open(path):
            words = line.split("#")[0].split()
            if len(words) == 4 and words[2] in ("xlo", "ylo"):
                box[words[2]] = float(words[1]) - float(words[0])
            elif words and words[0] in SECTIONS and len(words) == 1:
                section = words[0]
            elif section == "Atoms" and len(words) >= 6:
                atoms[int(words[0])] = (int(words[1]), float(words[3]), float(words[4]))
            elif section == "Bonds" and len(words) == 4:
                (segments if words[1] == "1" else adhesive).append((int(words[2]), int(words[3])))
            elif section == "Vertices" and len(words) >= 5:
                sigma[int(words[0])] = float(words[1])
        self.ids = sorted(atoms)
        index = {a: k for k, a in enumerate(self.ids)}
        self.cell = np.array([atoms[a][0] for a in self.ids])
        self.x = np.array([atoms[a][1:] for a in self.ids])
        self.sigma = np.array([sigma[a] for a in self.ids])
        self.box = np.array([box["xlo"], box["ylo"]])
        neighbours = collections.defaultdict(list)
        for a, b in segments:
            neighbours[index[a]].append(index[b])
            neighbours[index[b]].append(index[a])
        self.neighbours = dict(neighbours)
        self.rings = {c: self.ring(min(np.nonzero(self.cell == c)[0])) for c in set(self.cell)}
        self.bonds = sorted(tuple(sorted((index[a], index[b]))) for a, b in adhesive)
        self.stretch = {b: self.distance(*b) / self.contact(*b) for b in self.bonds}

    def ring(self, start):
        """The ring from its smallest ID, toward its ring neighbour of smaller ID."""
        ring = [start, min(self.neighbours[start])]
        while True:
            following = [n for n in self.neighbours[ring[-1]] if n != ring[-2]][0]
            if following == start:
                return ring
            ring.append(following)

    def distance(self, i, j):
        d = self.x[j] - self.x[i]
        d -= self.box * np.round(d / self.box)
        return math.hypot(*d)

    def contact(self, i, j):
        return 0.5 * (self.sigma[i] + self.sigma[j])

    def cell_pair(self, bond):
        return tuple(sorted((self.cell[bond[0]], self.cell[bond[1]])))


def neighbour_pairs(state):
    """(bonded cell pairs, contact-only cell pairs)."""
    d = state.x[:, None, :] - state.x[None, :, :]
    d -= state.box * np.round(d / state.box)
    r = np.sqrt((d ** 2).sum(-1))
    s = 0.5 * (state.sigma[:, None] + state.sigma[None, :])
    i, j = np.nonzero((r < s) & (state.cell[:, None] != state.cell[None, :]))
    contact = {tuple(sorted(p)) for p in zip(state.cell[i], state.cell[j])}
    bonded = {state.cell_pair(b) for b in state.bonds}
    return bonded, contact - bonded


def breaking_pass(state, order, z_per_cell_pair, rng):
    """The bonds one pass breaks, visiting them in 'order'."""
    left = set(state.bonds)
    per_vertex, per_cell = collections.Counter(), collections.Counter()
    for i, j in left:
        per_vertex[i] += 1
        per_vertex[j] += 1
        per_cell[state.cell[i]] += 1
        per_cell[state.cell[j]] += 1
    broken, pair, z = [], None, 0.0
    for visit in order:
        b = tuple(sorted(visit))
        m, n = state.cell[visit[0]], state.cell[visit[1]]
        if not z_per_cell_pair or (m, n) != pair:
            pair, z = (m, n), 0.5 * (per_cell[m] + per_cell[n]) + 1.0
        stretch = state.stretch[b]
        if stretch <= 1.0:
            continue
        barrier = 1.0 - 0.5 * (stretch - 1.0) ** 2
        edge = any(per_vertex[k] == 0 for v in b for k in state.neighbours[v])
        if barrier < 0:
            breaks = True
        elif z_per_cell_pair:    # the published code draws whether or not the bond can break
            breaks = math.exp(-BETA * barrier / z) > rng.random() and edge
        else:
            breaks = edge and rng.random() < math.exp(-BETA * barrier / z)
        if breaks:
            left.discard(b)
            broken.append(b)
            for v in b:
                per_vertex[v] -= 1
            per_cell[m] -= 1
            per_cell[n] -= 1
    return broken


def published_order(state):
    position = {v: k for ring in state.rings.values() for k, v in enumerate(ring)}
    def key(b):
        i, j = b if state.cell[b[0]] < state.cell[b[1]] else (b[1], b[0])
        return (state.cell[i], state.cell[j], position[i], position[j])
    return [b if state.cell[b[0]] < state.cell[b[1]] else (b[1], b[0])
            for b in sorted(state.bonds, key=key)]


def package_order(state):
    return sorted(state.bonds, key=lambda b: sorted((state.ids[b[0]], state.ids[b[1]])))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("data", nargs="+")
    p.add_argument("--passes", type=int, default=20000)
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args()
    for path in args.data:
        state = State(path)
        cells = len(state.rings)
        bonded, contact_only = neighbour_pairs(state)
        print(f"{path}: z {2 * (len(bonded) + len(contact_only)) / cells:.4f}: "
              f"{len(bonded)} bonded cell pairs, {len(contact_only)} contact-only "
              f"{sorted((int(a), int(b)) for a, b in contact_only)}; {len(state.bonds)} bonds")
        stretched = [b for b in state.bonds if state.stretch[b] > 1.0]
        print(f"  {len(stretched)} stretched (r > s), largest r/s "
              f"{max(state.stretch.values()):.4f} (r*/s {1 + math.sqrt(2):.4f})")
        pairs = collections.Counter(state.cell_pair(b) for b in state.bonds)
        for name, order, per_pair in [("published", published_order(state), True),
                                      ("package", package_order(state), False)]:
            rng = random.Random(args.seed)
            counts, lost = [], []
            for _ in range(args.passes):
                broken = breaking_pass(state, order, per_pair, rng)
                counts.append(len(broken))
                gone = collections.Counter(state.cell_pair(b) for b in broken)
                lost.append(sum(1 for q, k in gone.items() if k == pairs[q]))
            print(f"  {name} loop: {np.mean(counts):.2f} bonds broken per pass (sd "
                  f"{np.std(counts):.2f}), {np.mean(lost):.3f} cell pairs lose their last bond "
                  f"({args.passes} passes)")


if __name__ == "__main__":
    main()
