"""The broad phase: which pairs of bodies are close enough to be worth a narrow-phase test.

Every body has an axis-aligned bounding box (left, top, right, bottom) in px.
Two boxes, each grown by a margin, overlap when they overlap on both axes:

    not (a.right + m < b.left or b.right + m < a.left or a.bottom + m < b.top or b.bottom + m < a.top)

with m = base + reach[i] + reach[j] px (the accumulated solver's speculative
margin: SPECULATIVE_MARGIN plus how far each body can move in the step; 0 for
the lesson solver). A pair is only wanted if at least one of its bodies moves
(`moving[k]` True): two static (or sleeping) bodies never need a contact.

Two ways to find the pairs, with the same answer:

  all_pairs        the reference: test every pair i < j, N (N - 1) / 2 box tests.
  sweep_and_prune  the classic (Baraff 1992; Box2D's first broad phase): sort the
                   boxes by their left edge and sweep from left to right, keeping
                   the "active" boxes whose right edge the sweep has not passed.
                   A box meeting the sweep can only overlap the active ones, so
                   only pairs overlapping along x are tested on y. Cost: the sort,
                   N log N, plus one test per pair overlapping along x. Bodies
                   spread along x (a wide pile, a level) cost about N; a tall tower
                   (every box over the same x) is still N² / 2 - sweep along the
                   longer axis of the scene if that ever matters.
                   The sort is Python's own: numpy does not pay here. For 1000
                   boxes in pile order (nearly sorted already, which Python's sort
                   handles in about linear time) sorted() took 75 µs against 192 µs
                   for np.argsort with the conversions; in random order 510 against
                   514 µs; either way under 0.1 % of a 1000-crate step (0.5-1.6 s).

Both return (pairs, tested): the pairs (i, j), i < j, whose grown boxes overlap
and in which a body moves, sorted by (i, j) - the order of the all-pairs loop,
which the lesson solver's results depend on (it resolves contacts in turn) -
and `tested`, how many pairs the method compared boxes of (all_pairs: every
pair with a moving body; sweep_and_prune: every pair with a moving body whose
grown boxes overlap along x, i.e. the pairs the sweep met).
"""


def boxes_apart(box_a, box_b, margin):
    """True when boxes (left, top, right, bottom) px, each grown by `margin` px in the gap, do not overlap.

    a.right + m < b.left or b.right + m < a.left or a.bottom + m < b.top or b.bottom + m < a.top.
    """
    return (box_a[2] + margin < box_b[0] or box_b[2] + margin < box_a[0] or
            box_a[3] + margin < box_b[1] or box_b[3] + margin < box_a[1])


def pair_margin(i, j, reach, base):
    """The margin (px) of pair (i, j): base + reach[i] + reach[j], or just base without `reach`."""
    return base + reach[i] + reach[j] if reach is not None else base


def all_pairs(boxes, moving, reach=None, base=0.0, bounds=None):
    """The reference broad phase: every pair i < j with a moving body, tested box against box.

    boxes[k]: body k's box (left, top, right, bottom) px; moving[k]: whether body k moves;
    reach[k] (px, optional) and base (px): the margins (pair_margin); bounds: unused (the
    same arguments as sweep_and_prune). Returns (pairs, tested),
    pairs sorted by (i, j); tested = the number of pairs with a moving body, N (N - 1) / 2 at most.
    """
    pairs, tested = [], 0
    n = len(moving)
    for i in range(n):
        for j in range(i + 1, n):
            if not moving[i] and not moving[j]:
                continue
            tested += 1
            if not boxes_apart(boxes[i], boxes[j], pair_margin(i, j, reach, base)):
                pairs.append((i, j))
    return pairs, tested


def sweep_and_prune(boxes, moving, reach=None, base=0.0, bounds=None):
    """The same pairs as all_pairs, found by sorting the boxes' left edges and sweeping along x.

    Each body's x-interval [left - g, right + g] is grown by its share of the
    pair margin, g = base / 2 + reach[k] (+ a rounding slack of 1e-9 of the
    largest coordinate, so the sweep never drops a pair the exact test keeps).
    Sorted by the grown left edge, body k meets the active bodies (those whose
    grown right edge >= k's grown left edge): those overlap k along x, and the
    pair goes to the exact test boxes_apart with pair_margin - the same
    expression as all_pairs, so the answer is the same to the last bit.
    Moving and still bodies are kept in two active lists: a still body is only
    paired with moving ones, so pairs of still bodies are never met.
    bounds[k] (optional): a box known to contain boxes[k] (for example pos ± the
    bounding radius), used for the sweep, so that `boxes` may compute a body's
    exact box only when one of its pairs reaches the exact test.
    Returns (pairs, tested) as all_pairs; tested = the pairs met by the sweep.
    """
    n = len(moving)
    bounds = boxes if bounds is None else bounds
    if reach is None:
        grow = [base / 2 + 0.0] * n
    else:
        grow = [base / 2 + reach[k] for k in range(n)]
    largest = max((max(abs(bounds[k][0]), abs(bounds[k][2])) + grow[k] for k in range(n)), default=0.0)
    slack = 1e-9 * (1.0 + largest)
    lo = [bounds[k][0] - grow[k] - slack for k in range(n)]
    hi = [bounds[k][2] + grow[k] + slack for k in range(n)]
    active_moving, active_still = [], []
    pairs, tested = [], 0
    for k in sorted(range(n), key=lo.__getitem__):
        left = lo[k]
        met = active_moving = [a for a in active_moving if hi[a] >= left]
        if moving[k]:
            active_still = [a for a in active_still if hi[a] >= left]
            met = active_moving + active_still
            active_moving.append(k)
        else:
            active_still.append(k)   # pruned when the next moving body arrives
        if not met:
            continue
        tested += len(met)
        box_k = boxes[k]  # only now: `boxes` may compute a box on first use
        for a in met:  # boxes_apart(boxes[i], boxes[j], pair_margin(i, j, reach, base)), written out
            i, j = (a, k) if a < k else (k, a)
            box_i, box_j = (boxes[a], box_k) if a < k else (box_k, boxes[a])
            m = base + reach[i] + reach[j] if reach is not None else base
            if not (box_i[2] + m < box_j[0] or box_j[2] + m < box_i[0] or
                    box_i[3] + m < box_j[1] or box_j[3] + m < box_i[1]):
                pairs.append((i, j))
    pairs.sort()
    return pairs, tested


def sweep_boxes(boxes, moving):
    """sweep_and_prune(boxes, moving) without margins or bounds (the lesson solver's search), written out.

    With reach None and base 0 every grow term is +0.0, which changes no
    comparison (x + 0.0 differs from x only for -0.0, and -0.0 == 0.0), so the
    slack, the sweep order, the pairs and `tested` are the same as
    sweep_and_prune's (tests/test_broadphase.py holds the two equal).
    """
    n = len(boxes)
    largest = 0.0
    for left, _, right, _ in boxes:
        far = max(abs(left), abs(right))
        if far > largest:
            largest = far
    slack = 1e-9 * (1.0 + largest)
    lo = [box[0] - slack for box in boxes]
    hi = [box[2] + slack for box in boxes]
    active_moving, active_still = [], []
    pairs, tested = [], 0
    for k in sorted(range(n), key=lo.__getitem__):
        left = lo[k]
        met = active_moving = [a for a in active_moving if hi[a] >= left]
        if moving[k]:
            if active_still:
                active_still = [a for a in active_still if hi[a] >= left]
                met = active_moving + active_still
            else:
                met = active_moving[:]
            active_moving.append(k)
        else:
            active_still.append(k)
        if not met:
            continue
        tested += len(met)
        _, top, right, bottom = box_k = boxes[k]
        for a in met:
            box = boxes[a]
            if not (box[2] < box_k[0] or right < box[0] or box[3] < top or bottom < box[1]):
                pairs.append((a, k) if a < k else (k, a))
    pairs.sort()
    return pairs, tested
