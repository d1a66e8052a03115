"""A collision test's answer in a declared step: None (apart) or (normal, depth), as probe_kit.sat_answer reads it.

same_hit compares one with the lesson's (a Step's `same`), hit_text and hit_difference word it for the evidence
line: any lab whose student writes sat(), circle_polygon() or another test that answers (normal, depth) or None.
"""
from .common import close, same_point
from .lab_checks import vec_text

TOUCHING = 1e-6   # px: a depth this small may stand for "apart" when the lesson says apart (exactly touching)


def same_hit(got, want):
    """got (sat_answer's plain data) is the lesson's: the same normal and depth, or apart (or exactly touching)."""
    if want is None:
        return got is None or ("bad" not in got and got["depth"] <= TOUCHING)
    return got is not None and "bad" not in got and same_point(got["normal"], want["normal"]) and \
        close(got["depth"], want["depth"])


def hit_text(hit):
    """"normal (x, y), depth d px", "None (apart)" or what is wrong with a malformed answer."""
    if hit is None:
        return "None (apart)"
    return hit["bad"] if "bad" in hit else f"normal {vec_text(hit['normal'])}, depth {hit['depth']:.3f} px"


def hit_difference(got, want):
    """"<yours>; expected <the lesson's>", of the normal alone or the depth alone when only it differs; a malformed
    answer alone."""
    if got and "bad" in got:
        return got["bad"]
    if got and want and close(got["depth"], want["depth"]):
        return f"normal {vec_text(got['normal'])}; expected {vec_text(want['normal'])}"
    if got and want and same_point(got["normal"], want["normal"]):
        return f"depth {got['depth']:.3f} px; expected {want['depth']:.3f} px"
    return f"{hit_text(got)}; expected {hit_text(want)}"
