"""Sparsity of the constraint Jacobian and of the matrices the right-hand side factorises.

Every constraint row (a joint's two rows, a driver's one) touches at most two bodies, so the
Jacobian is stored as (rows, 6): the x, y, phi entries of the row's first and second body.
The right-hand side factorises either Phi_q M^-1 Phi_q^T (rows x rows, Baumgarte) or
M + Phi_q^T W Phi_q (coordinates x coordinates, augmented Lagrangian), both in envelope
storage (``kernels.linalg``). Their envelopes are narrow when bodies joined to each other are
numbered close together: the bodies are put in reverse Cuthill-McKee order of the graph of
joints (Cuthill and McKee 1969; George and Liu 1981, sec. 4.3), a handful of lines written
here so that the runtime needs no scipy. A chain or a tree then costs linear time.
"""

from __future__ import annotations

from collections import deque
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..kernels.jacobian import ENTRIES  # per row: (x, y, phi) of its first body, then second


class Pattern(NamedTuple):
    """Index tables of the sparse constraint Jacobian and the two envelopes."""

    row_coord: NDArray[np.int64]  # (m, 6) coordinate of each Jacobian entry, -1 for the ground
    row_order: NDArray[np.int64]  # (m,) position of each row in the Schur envelope
    row_first: NDArray[np.int64]  # (m,) first column of each envelope row
    row_ptr: NDArray[np.int64]  # (m + 1,) start of each envelope row
    row_pairs: NDArray[np.int64]  # (p, 6) Schur terms: envelope index, r1, e1, r2, e2, coord
    coord_order: NDArray[np.int64]  # (n,) position of each coordinate in the mass envelope
    coord_first: NDArray[np.int64]  # (n,)
    coord_ptr: NDArray[np.int64]  # (n + 1,)
    coord_diagonal: NDArray[np.int64]  # (n,) envelope index of each coordinate's diagonal
    row_entry_pairs: NDArray[np.int64]  # (m, 36) envelope index of entries e1, e2, or -1


def _cuthill_mckee(neighbours: list[set[int]]) -> list[int]:
    """Reverse Cuthill-McKee order of a graph's nodes (every component, lowest degree first)."""
    order: list[int] = []
    seen = [False] * len(neighbours)
    for start in sorted(range(len(neighbours)), key=lambda v: len(neighbours[v])):
        if seen[start]:
            continue
        seen[start] = True
        queue = deque([start])
        while queue:
            node = queue.popleft()
            order.append(node)
            for nxt in sorted(neighbours[node], key=lambda v: (len(neighbours[v]), v)):
                if not seen[nxt]:
                    seen[nxt] = True
                    queue.append(nxt)
    return order[::-1]


def _envelope(position: NDArray[np.int64], couples: list[set[int]]) -> tuple[NDArray, NDArray]:
    """First column and row starts of the envelope; couples[v]: items coupled with v."""
    size = position.shape[0]
    first = np.empty(size, dtype=np.int64)
    for item in range(size):
        first[position[item]] = min(position[c] for c in couples[item] | {item})
    ptr = np.zeros(size + 1, dtype=np.int64)
    ptr[1:] = np.cumsum(np.arange(size) - first + 1)
    return first, ptr


def _index(first: NDArray, ptr: NDArray, i: int, j: int) -> int:
    """Flat envelope index of entry (i, j), i >= j."""
    return int(ptr[i] + j - first[i])


def build_pattern(row_bodies: NDArray[np.int64], n_bodies: int) -> Pattern:
    """The index tables for constraint rows joining row_bodies (m, 2) (-1: the ground)."""
    m = row_bodies.shape[0]
    n = 3 * n_bodies
    row_coord = np.full((m, ENTRIES), -1, dtype=np.int64)
    for r, pair in enumerate(row_bodies):
        if pair[0] >= 0 and pair[0] == pair[1]:
            raise ValueError(f"constraint row {r} joins body {pair[0]} to itself")
        for side, body in enumerate(pair):
            if body >= 0:
                row_coord[r, 3 * side : 3 * side + 3] = 3 * body + np.arange(3)

    joined = [set() for _ in range(n_bodies)]
    for i, j in row_bodies:
        if i >= 0 and j >= 0:
            joined[i].add(int(j))
            joined[j].add(int(i))
    body_position = np.empty(n_bodies, dtype=np.int64)
    body_position[_cuthill_mckee(joined)] = np.arange(n_bodies)

    coord_order = (3 * body_position[:, None] + np.arange(3)).ravel()
    coord_couples = [
        {3 * b + k for b in joined[c // 3] | {c // 3} for k in range(3)} for c in range(n)
    ]
    coord_first, coord_ptr = _envelope(coord_order, coord_couples)
    row_entry_pairs = np.full((m, ENTRIES * ENTRIES), -1, dtype=np.int64)
    for r in range(m):
        for e1 in range(ENTRIES):
            for e2 in range(ENTRIES):
                c1, c2 = row_coord[r, e1], row_coord[r, e2]
                if c1 >= 0 and c2 >= 0 and coord_order[c1] >= coord_order[c2]:
                    row_entry_pairs[r, ENTRIES * e1 + e2] = _index(
                        coord_first, coord_ptr, coord_order[c1], coord_order[c2]
                    )

    key = [
        (
            min(body_position[b] for b in pair if b >= 0),
            max(body_position[b] for b in pair if b >= 0),
        )
        if (pair >= 0).any()
        else (n_bodies, n_bodies)
        for pair in row_bodies
    ]
    row_order = np.empty(m, dtype=np.int64)
    row_order[sorted(range(m), key=lambda r: key[r])] = np.arange(m)
    touching: list[list[tuple[int, int]]] = [[] for _ in range(n)]  # (row, entry) per coord
    for r in range(m):
        for e in range(ENTRIES):
            if row_coord[r, e] >= 0:
                touching[row_coord[r, e]].append((r, e))
    row_couples = [set() for _ in range(m)]
    for entries in touching:
        for r1, _ in entries:
            row_couples[r1].update(r2 for r2, _ in entries)
    row_first, row_ptr = _envelope(row_order, row_couples)
    pairs = [
        (_index(row_first, row_ptr, row_order[r1], row_order[r2]), r1, e1, r2, e2, coord)
        for coord, entries in enumerate(touching)
        for r1, e1 in entries
        for r2, e2 in entries
        if row_order[r1] >= row_order[r2]
    ]
    return Pattern(
        row_coord=row_coord,
        row_order=row_order,
        row_first=row_first,
        row_ptr=row_ptr,
        row_pairs=np.array(pairs, dtype=np.int64).reshape(len(pairs), 6),
        coord_order=coord_order,
        coord_first=coord_first,
        coord_ptr=coord_ptr,
        coord_diagonal=np.array(
            [_index(coord_first, coord_ptr, i, i) for i in coord_order], dtype=np.int64
        ),
        row_entry_pairs=row_entry_pairs,
    )
