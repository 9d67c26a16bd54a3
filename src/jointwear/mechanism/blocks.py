"""The blocks of a mechanism: the biconnected components of its graph of bodies and rows.

Nodes are the bodies and the ground; each constraint row is an edge between the two it
joins. A block is a largest set of edges in which every two lie on a common cycle (rows
between the same two nodes share their block): a bar of a chain is a block of its own, the
four bars of a four-bar with the ground one block. Found by depth-first search with low
points (Hopcroft and Tarjan 1973), iterative, in time linear in the rows; scipy.sparse.csgraph
has connected components but not these.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray


def row_blocks(ends: NDArray[np.int64], nodes: int) -> NDArray[np.int64]:
    """The block of every row, numbered from 0.

    ``ends`` (m, 2): the nodes each row joins, in 0 ... ``nodes`` - 1. A row joining a node
    to itself is a block of its own.
    """
    low_end, high_end = ends.min(axis=1), ends.max(axis=1)
    edges, edge_of_row = np.unique(low_end * nodes + high_end, return_inverse=True)
    label = _edge_blocks(np.column_stack([edges // nodes, edges % nodes]), nodes)
    blocks = label[edge_of_row.ravel()]
    loops = np.flatnonzero(low_end == high_end)
    blocks[loops] = label.max(initial=-1) + 1 + np.arange(loops.size)
    return blocks


def _edge_blocks(edges: NDArray[np.int64], nodes: int) -> NDArray[np.int64]:
    """The block of every edge of a simple graph (an edge from a node to itself: -1)."""
    neighbours: list[list[tuple[int, int]]] = [[] for _ in range(nodes)]
    for e, (a, b) in enumerate(edges.tolist()):
        if a != b:
            neighbours[a].append((b, e))
            neighbours[b].append((a, e))
    depth, low = [-1] * nodes, [0] * nodes
    label = np.full(edges.shape[0], -1, dtype=np.int64)
    found, open_edges = 0, []
    for root in range(nodes):
        if depth[root] >= 0:
            continue
        depth[root] = 0
        stack = [(root, -1, iter(neighbours[root]))]  # node, the edge it was reached by
        while stack:
            node, via, rest = stack[-1]
            for nxt, e in rest:
                if depth[nxt] < 0:  # a tree edge: go down
                    open_edges.append(e)
                    depth[nxt] = low[nxt] = depth[node] + 1
                    stack.append((nxt, e, iter(neighbours[nxt])))
                    break
                if e != via and depth[nxt] < depth[node]:  # an edge back up the tree
                    open_edges.append(e)
                    low[node] = min(low[node], depth[nxt])
            else:  # every edge of node seen: back up to its parent
                stack.pop()
                if not stack:
                    continue
                parent = stack[-1][0]
                low[parent] = min(low[parent], low[node])
                if low[node] >= depth[parent]:  # the parent cuts node's subtree off: a block
                    while True:
                        e = open_edges.pop()
                        label[e] = found
                        if e == via:
                            break
                    found += 1
    return label
