"""Sparsity of the constraint Jacobian and of the matrices the right-hand side factorises.

Every constraint row (a joint's two rows, a driver's one) touches at most two bodies, so the
Jacobian is stored as (rows, 6): the x, y, phi entries of the row's first and second body.
The right-hand side factorises either Phi_q M^-1 Phi_q^T (rows x rows, Baumgarte) or
M + Phi_q^T W Phi_q (coordinates x coordinates, augmented Lagrangian), both in envelope
storage (``kernels.linalg``). Their envelopes are narrow when bodies joined to each other are
numbered close together: the bodies are put in reverse Cuthill-McKee order of the graph of
joints (Cuthill and McKee 1969; George and Liu 1981, sec. 4.3), a handful of lines written
here so that the runtime needs no scipy. A chain or a tree then costs linear time, and so
does building the tables (array operations, no loop over rows).
"""

from __future__ import annotations

from collections import deque
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..kernels.jacobian import ENTRIES  # per row: (x, y, phi) of its first body, then second
from .blocks import row_blocks


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
    open_tree: bool  # the rows join the bodies without a loop (``joins_without_loop``)


def joins_without_loop(row_bodies: NDArray[np.int64], n_bodies: int) -> bool:
    """Whether rows joining row_bodies (m, 2) (-1: the ground) close no loop of bodies.

    Rows between the same two bodies (a joint's rows, a driver beside it) count as one edge;
    the graph has no loop when each of its blocks is a single edge.
    """
    nodes = row_bodies + 1  # the ground is node 0
    edges = np.unique(np.sort(nodes, axis=1), axis=0).shape[0]
    return bool(np.unique(row_blocks(nodes, n_bodies + 1)).size == edges)


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


def _envelope(position: NDArray[np.int64], reach: NDArray[np.int64]) -> tuple[NDArray, NDArray]:
    """First column and row starts of the envelope; reach[v]: the lowest position coupled with v."""
    first = np.empty(position.shape[0], dtype=np.int64)
    first[position] = np.minimum(reach, position)
    ptr = np.zeros(position.shape[0] + 1, dtype=np.int64)
    ptr[1:] = np.cumsum(np.arange(position.shape[0]) - first + 1)
    return first, ptr


def _lowest(position: NDArray[np.int64], pairs: NDArray[np.int64]) -> NDArray[np.int64]:
    """Per node, the lowest ``position`` among its own and those of the nodes it pairs with.

    ``pairs`` (m, 2): nodes paired by each row, -1 for the ground (no position).
    """
    size = position.shape[0]
    lowest = np.append(position, 0)  # the last: the ground's, never read
    placed = np.append(position, np.iinfo(np.int64).max)
    both = np.where(pairs >= 0, pairs, size)
    np.minimum.at(lowest, both[:, 0], placed[both[:, 1]])
    np.minimum.at(lowest, both[:, 1], placed[both[:, 0]])
    return lowest[:size]


def build_pattern(row_bodies: NDArray[np.int64], n_bodies: int) -> Pattern:
    """The index tables for constraint rows joining row_bodies (m, 2) (-1: the ground)."""
    m = row_bodies.shape[0]
    looped = np.flatnonzero((row_bodies[:, 0] >= 0) & (row_bodies[:, 0] == row_bodies[:, 1]))
    if looped.size:
        r = int(looped[0])
        raise ValueError(f"constraint row {r} joins body {row_bodies[r, 0]} to itself")
    body_of_entry = np.repeat(row_bodies, 3, axis=1)  # (m, ENTRIES)
    row_coord = np.where(body_of_entry >= 0, 3 * body_of_entry + np.tile(np.arange(3), 2), -1)

    joined = [set() for _ in range(n_bodies)]
    for i, j in row_bodies[(row_bodies >= 0).all(axis=1)].tolist():
        joined[i].add(j)
        joined[j].add(i)
    body_position = np.empty(n_bodies, dtype=np.int64)
    body_position[_cuthill_mckee(joined)] = np.arange(n_bodies)

    # a coordinate couples with the coordinates of its body and of the bodies joined to it
    coord_order = (3 * body_position[:, None] + np.arange(3)).ravel()
    body_reach = _lowest(body_position, row_bodies)
    coord_first, coord_ptr = _envelope(coord_order, np.repeat(3 * body_reach, 3))
    row_entry_pairs = _entry_pairs(row_coord, coord_order, coord_first, coord_ptr)

    # rows in order of their bodies' positions (rows on the ground alone last); a row couples
    # with every row sharing a body with it
    placed = np.where(row_bodies >= 0, body_position[row_bodies], n_bodies)
    key_low, key_high = placed.min(axis=1), np.where(row_bodies >= 0, placed, -1).max(axis=1)
    key_high = np.where(key_high < 0, n_bodies, key_high)
    row_order = np.empty(m, dtype=np.int64)
    row_order[np.lexsort((key_high, key_low))] = np.arange(m)
    lowest_row = np.full(n_bodies + 1, np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(lowest_row, np.where(row_bodies >= 0, row_bodies, n_bodies).ravel(),
                  np.repeat(row_order, 2))  # fmt: skip
    row_reach = np.where(row_bodies >= 0, lowest_row[row_bodies], row_order[:, None]).min(axis=1)
    row_first, row_ptr = _envelope(row_order, row_reach)
    return Pattern(
        row_coord=row_coord,
        row_order=row_order,
        row_first=row_first,
        row_ptr=row_ptr,
        row_pairs=_schur_pairs(row_coord, row_order, row_first, row_ptr),
        coord_order=coord_order,
        coord_first=coord_first,
        coord_ptr=coord_ptr,
        coord_diagonal=coord_ptr[coord_order] + coord_order - coord_first[coord_order],
        row_entry_pairs=row_entry_pairs,
        open_tree=joins_without_loop(row_bodies, n_bodies),
    )


def _entry_pairs(row_coord: NDArray, order: NDArray, first: NDArray, ptr: NDArray) -> NDArray:
    """(m, 36) mass-envelope index of each row's entry pair (e1, e2), e1 at or below e2; -1."""
    m = row_coord.shape[0]
    placed = np.where(row_coord >= 0, order[row_coord], -1)
    i, j = placed[:, :, None], placed[:, None, :]  # the entries e1 (rows), e2 (columns)
    inside = (i >= 0) & (j >= 0) & (i >= j)
    safe = np.where(inside, i, 0)
    index = ptr[safe] + np.where(inside, j, 0) - first[safe]
    return np.where(inside, index, -1).reshape(m, ENTRIES * ENTRIES)


def _schur_pairs(row_coord: NDArray, order: NDArray, first: NDArray, ptr: NDArray) -> NDArray:
    """(p, 6) Schur terms: envelope index, r1, e1, r2, e2, coordinate.

    One for every two entries (r1, e1), (r2, e2) in one coordinate, r1 at or below r2 in the
    envelope's order; by coordinate, then r1 and e1, then r2 and e2.
    """
    rows, entries = np.nonzero(row_coord >= 0)  # by row, then entry
    coords = row_coord[rows, entries]
    by_coord = np.argsort(coords, kind="stable")
    rows, entries, coords = rows[by_coord], entries[by_coord], coords[by_coord]
    start = np.searchsorted(coords, coords)  # each entry's group: the entries of its coordinate
    count = np.searchsorted(coords, coords, side="right") - start
    one = np.repeat(np.arange(coords.size), count)
    other = start[one] + np.arange(one.size) - np.repeat(np.cumsum(count) - count, count)
    keep = order[rows[one]] >= order[rows[other]]
    one, other = one[keep], other[keep]
    i, j = order[rows[one]], order[rows[other]]
    return np.column_stack(
        [ptr[i] + j - first[i], rows[one], entries[one], rows[other], entries[other], coords[one]]
    ).astype(np.int64)
