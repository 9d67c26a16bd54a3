"""The rank of the constraint Jacobian, and which equations depend on others.

The numerical rank counts the singular values above ``RANK_TOLERANCE`` times the largest (at
least 1); the rows involved in a dependence are those with a share above ``INVOLVED`` in the
left singular vectors of the others (the left null space: self-stresses, reactions that
could grow without moving anything). A small Jacobian (``Jacobian.small``) is decomposed
whole by LAPACK's SVD. A larger one block by block (``blocks.py``): moving the bodies a row
joins together, as one rigid body, keeps its constraint met at a pose where it holds, so
there the row is orthogonal to such motions, unless it holds a body to the ground. A
self-stress is then balanced within each block that a body cuts off from the ground, on
that body too: the left null space is the sum of the blocks' own, and the rank the sum of
the blocks' ranks, each from the SVD of the block's rows in its bodies' coordinates (a
body's three columns). That holds at an assembled pose, where the set-up asks, to the
assembly's tolerance; the tolerance is then each block's. A chain's blocks are its single
bars, a four-bar's is its loop: the cost grows with the rows and with the cube of the
largest loop system, not of the whole mechanism.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from .background import off_main_thread
from .blocks import row_blocks
from .jacobian import Jacobian

RANK_TOLERANCE = 1e-9  # of the largest singular value, or absolute below 1
INVOLVED = 1e-6  # share in the left null space of a row involved in a dependence
INLINE_SVD = 10**6  # an SVD of a stack this size times its matrices' smaller side (a few
# ms) or less runs on the calling thread; a larger one on a worker (interrupts.off_main_thread)


class Dependence(NamedTuple):
    """The rank of a Jacobian and the rows that depend on others."""

    rank: int
    involved: NDArray[np.bool_]  # (rows,) a share in a dependence


def dependence(jacobian: Jacobian) -> Dependence:
    """The numerical rank of Phi_q and the rows involved in its dependences."""
    if jacobian.small:
        return dense_dependence(jacobian.dense())
    return block_dependence(jacobian)


def dense_dependence(matrix: NDArray[np.float64]) -> Dependence:
    """``dependence`` of a dense (rows, n) matrix, from its whole SVD."""
    ranks, involved = _svd_dependence(matrix[None])
    return Dependence(int(ranks[0]), involved[0])


def block_dependence(jacobian: Jacobian) -> Dependence:
    """``dependence`` from the SVD of each block of rows, in the block's own coordinates."""
    coord, rows = jacobian.coord, jacobian.rows
    bodies = jacobian.columns // 3
    ends = np.where(coord[:, [0, 3]] >= 0, coord[:, [0, 3]] // 3, bodies)  # the ground last
    block = row_blocks(ends, bodies + 1)
    by_block = np.argsort(block, kind="stable")
    size = np.bincount(block, minlength=block.max(initial=-1) + 1)
    place = np.empty(rows, dtype=np.int64)  # each row's place in its block
    place[by_block] = np.arange(rows) - np.repeat(np.cumsum(size) - size, size)
    # the bodies of each block, numbered from 0 in each: (block, body) pairs in order
    entry_rows, slots = np.nonzero(coord >= 0)
    keys = block[entry_rows] * bodies + coord[entry_rows, slots] // 3
    pairs, pair_of_entry = np.unique(keys, return_inverse=True)
    width = np.bincount(pairs // bodies, minlength=size.shape[0])
    local_body = np.arange(pairs.size) - np.repeat(np.cumsum(width) - width, width)
    column = 3 * local_body[pair_of_entry.ravel()] + coord[entry_rows, slots] % 3

    rank, involved = 0, np.zeros(rows, dtype=bool)
    shapes = size * (3 * width.max(initial=0) + 1) + 3 * width  # one number per (rows, cols)
    for shape in np.unique(shapes):
        members = np.flatnonzero(shapes == shape)
        stack = np.zeros((members.size, size[members[0]], 3 * width[members[0]]))
        index = np.full(size.shape[0], -1)
        index[members] = np.arange(members.size)
        mine = index[block[entry_rows]] >= 0
        stack[index[block[entry_rows[mine]]], place[entry_rows[mine]], column[mine]] = (
            jacobian.entries[entry_rows[mine], slots[mine]]
        )
        ranks, shares = _svd_dependence(stack)
        rank += int(ranks.sum())
        in_members = index[block] >= 0
        involved[in_members] = shares[index[block[in_members]], place[in_members]]
    return Dependence(rank, involved)


def _svd_dependence(stack: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
    """Ranks (k,) and rows involved in a dependence (k, rows) of a stack of matrices."""
    count, rows, columns = stack.shape
    if rows == 0:
        return np.zeros(count, dtype=np.int64), np.zeros((count, 0), dtype=bool)
    if columns == 0:
        return np.zeros(count, dtype=np.int64), np.ones((count, rows), dtype=bool)
    if stack.size * min(rows, columns) > INLINE_SVD:  # a Ctrl-C is answered during a long one
        u, sv, _ = off_main_thread(lambda: np.linalg.svd(stack))
    else:
        u, sv, _ = np.linalg.svd(stack)
    tolerance = RANK_TOLERANCE * np.maximum(1.0, sv[:, :1])
    padded = np.concatenate([sv, np.zeros((count, rows - sv.shape[1]))], axis=1)
    null = padded <= tolerance  # (count, rows): the left singular vectors of the null space
    weights = (np.abs(u) * null[:, None, :]).sum(axis=2)
    return (sv > tolerance).sum(axis=1), weights > INVOLVED
