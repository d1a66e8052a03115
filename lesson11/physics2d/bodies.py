"""Rigid bodies: a shape with a position, an angle, a mass and how it moves.

A body moves with `vel` (px/s) and turns with `omega` (rad/s). Mass 0 means
static: inv_mass = inv_inertia = 0, so no impulse or push can move or turn it.
Its settings (pos, angle, mass, inertia, restitution, friction) are checked
whenever they are set, in Body(...) or later (settings.setting), and setting
mass or inertia keeps the fields derived from them in step.
"""
import math

from .settings import setting
from .shapes import Circle, Polygon, WorldPoints
from .vectors import Vector2, finite_number, finite_vector, spin_velocity


_UNSET = object()   # what a body holds before its first pos (Body.__new__, before __init__)


# ---------------------------------------------------------------- the checks of Body's settings
# Each returns check(body, value) for settings.setting: the value to keep, or a one-line ValueError.

def _vector(name, what):
    """A pair of finite numbers, kept as the body's own Vector2 (so no two bodies share one)."""
    private = "_" + name

    def check(body, value):
        if value is getattr(body, private, _UNSET):
            return value  # `body.pos += v` changed the body's own vector in place: World's end-of-step check sees it
        return finite_vector(value, what)
    return check


def _number(what, low=None, high=None):
    """A finite number, optionally low <= value (<= high); `what` names it in the error."""
    def check(_, value):
        value = finite_number(value, what)
        if low is not None and value < low:
            raise ValueError(f"{what} must be >= {low:g}, got {value}" if high is None
                             else f"{what} must be between {low:g} and {high:g}, got {value}")
        if high is not None and value > high:
            raise ValueError(f"{what} must be between {low:g} and {high:g}, got {value}")
        return value
    return check


def _mass(body, value):
    """A mass >= 0; sets inv_mass, inertia (the shape's) and inv_inertia to match; 0 makes the body static."""
    mass = finite_number(value, "body mass")
    if mass < 0:
        raise ValueError(f"body mass must be >= 0 (0 means static), got {mass}")
    if mass == 0:  # static: infinite mass and inertia
        body.inv_mass, body._inertia, body.inv_inertia = 0.0, 0.0, 0.0
        return mass
    inertia = body.shape.inertia(mass)
    if not (0 < inertia < math.inf and 1 / mass < math.inf and 1 / inertia < math.inf):
        raise ValueError(f"body mass {mass:g} with this shape gives a moment of inertia of {inertia:g}, "
                         "too small or too large to invert; use a mass and size nearer 1")
    body.inv_mass, body._inertia, body.inv_inertia = 1 / mass, inertia, 1 / inertia
    return mass


def _inertia(body, value):
    """A moment of inertia > 0 (math.inf: cannot turn) for a dynamic body, 0 for a static one; sets inv_inertia."""
    try:
        inertia = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"body inertia must be a number, got {value!r}") from None
    if math.isnan(inertia):
        raise ValueError(f"body inertia must be finite (or math.inf: a body that cannot turn), got {inertia}")
    if body.mass == 0:
        if inertia != 0:
            raise ValueError(f"a static body (mass 0) takes no inertia, got inertia={inertia}")
        return 0.0
    if inertia <= 0:
        raise ValueError(f"body inertia must be > 0 (mass·px²), got {inertia}")
    if 1 / inertia == math.inf:
        raise ValueError(f"body inertia {inertia:g} is too small to invert; use a mass and size nearer 1")
    body.inv_inertia = 1 / inertia
    return inertia


class Body:
    """A rigid body.

    Attributes (all public, all in px, s, rad):
      shape          a Polygon or a Circle (shapes.py)
      pos, vel       centre of mass (px) and its velocity (px/s), Vector2
      angle, omega   rotation (rad, positive = clockwise on screen) and spin (rad/s)
      mass, inv_mass mass and 1/mass; both 0 for a static body
      inertia, inv_inertia  moment of inertia and its inverse; 0 for static
      restitution    bounciness e in [0, 1], default 0.2
      friction       friction coefficient μ >= 0, default 0.6
      bullet         True asks the World for swept (continuous) collision tests
      color          RGB used by draw.py

    `shape` may also be a list of points (a convex polygon) for the lesson's
    Body(points, pos, mass) form.

    `inertia` (mass·px²), when given, is used in place of shape.inertia(mass):
    a lab that computes the moment of inertia with its own polygon_inertia
    passes it here. It must be a number > 0 (math.inf: a body that cannot
    turn), and only a dynamic body (mass > 0) takes one.

    pos, angle, mass, inertia, restitution and friction are checked whenever
    they are set, here or later, with the same one-line ValueError;
    help(Body.mass) and the others say what each is, its unit and default.
    inv_mass and inv_inertia follow mass and inertia: set those, and the
    solvers read the inverses (a static body is one whose inv_mass is 0).
    vel and omega are checked here and stay plain attributes: the lesson's
    apply_impulse sets each of them at every contact point in every pass
    (about 6,700 sets a step in the lab's 12-crate pile), and checking each
    set made the lab's step 1.29 times as long (lesson11/bench/README.md,
    "physics2d's choices, measured"). Instead World.add() checks them, the
    start of every step checks each body's vel and omega (World.check_motion,
    one line naming the body and the field), and the end of every step checks
    that the step left every body finite.

    >>> from lesson11.physics2d import Body, box_points
    >>> crate = Body(box_points(40, 40), (100, 100), mass=2)
    >>> crate.inv_mass, round(crate.inertia, 2)
    (0.5, 533.33)
    >>> crate.mass = 0       # static from now on, in every derived field
    >>> crate.inv_mass, crate.inertia, crate.inv_inertia, crate.is_static
    (0.0, 0.0, 0.0, True)
    >>> crate.restitution = 5
    Traceback (most recent call last):
    ...
    ValueError: body restitution must be between 0 and 1, got 5.0
    """

    pos = setting("pos", _vector("pos", "body position"), """Position of the centre of mass (px), a pygame Vector2.

        y grows downward. Set it to any pair (x, y) of finite numbers: the body
        keeps its own Vector2 (a copy), so two bodies never share one.
        `body.pos += v` and `body.pos.x = x` change that vector in place;
        World checks those at the end of each step. Default (0, 0).""")
    angle = setting("angle", _number("body angle"), """Rotation (rad) of the shape from its local axes.

        Positive turns clockwise on screen (y grows downward). Any finite
        number; it is not wrapped to [0, 2π). Default 0.""")
    mass = setting("mass", _mass, """Mass (the course's unit: a w × h px crate has w·h/1000); 0 means static.

        Setting it recomputes inv_mass = 1 / mass, inertia = shape.inertia(mass)
        (polygon_inertia, or ½ m r² for a circle; an inertia given before is
        replaced, so set inertia after mass to keep your own) and inv_inertia.
        0 makes the body static in every field: inv_mass, inertia and
        inv_inertia all 0, so nothing moves or turns it. A finite number >= 0.
        Default 1.

        >>> from lesson11.physics2d import Body, Circle
        >>> ball = Body(Circle(10), (0, 0), mass=2)
        >>> ball.inertia, ball.inv_mass      # ½ m r²
        (100.0, 0.5)
        >>> ball.mass = 4
        >>> ball.inertia, ball.inv_mass, ball.inv_inertia
        (200.0, 0.25, 0.005)
        >>> ball.mass = -1
        Traceback (most recent call last):
        ...
        ValueError: body mass must be >= 0 (0 means static), got -1.0""")
    inertia = setting("inertia", _inertia, """Moment of inertia (mass·px²) about the centre of mass.

        Setting it sets inv_inertia = 1 / inertia. A number > 0 for a
        dynamic body; math.inf makes one that cannot turn
        (inv_inertia 0). A static body (mass 0) has 0 and takes no other.
        Default shape.inertia(mass), recomputed whenever mass is set.""")
    restitution = setting("restitution", _number("body restitution", 0, 1), """Bounciness e in [0, 1].

        0 stops dead at impact, 1 bounces back at the impact speed; a pair
        uses the smaller e of its two bodies, and impacts slower than the
        world's resting_speed do not bounce. Default 0.2.""")
    friction = setting("friction", _number("body friction", 0), """Friction coefficient μ >= 0.

        A pair uses √(μA μB): the friction impulse is at most μ times the
        normal impulse (Coulomb). 0 is ice. Default 0.6.""")

    def __init__(self, shape, pos=(0, 0), mass=1.0, angle=0.0, vel=(0, 0), omega=0.0,
                 restitution=0.2, friction=0.6, color=(200, 150, 90), bullet=False, inertia=None):
        if not isinstance(shape, (Polygon, Circle)):
            shape = Polygon(shape)
        self.shape = shape
        self.pos = pos           # each setting checks what it is given (above)
        self.vel = finite_vector(vel, "body velocity")   # vel and omega: plain attributes (see the class docstring)
        self.angle = angle
        self.omega = finite_number(omega, "body omega")
        self.mass = mass         # also sets inv_mass, inertia, inv_inertia
        self.restitution = restitution
        self.friction = friction
        self.color = color
        self.bullet = bool(bullet)
        self.asleep = False    # "sleep" effect: a sleeping body is not integrated (sleep.py)
        self.sleep_time = 0.0  # s its speed and spin have stayed under the world's sleep thresholds
        if inertia is not None:
            self.inertia = inertia   # also sets inv_inertia

    @classmethod
    def from_world_points(cls, points, mass=0.0, **settings):
        """A polygon body whose world corners are `points` (px): pos is their centroid, angle 0."""
        shape = Polygon(points)
        centre = Vector2(points[0]) - shape.points[0]
        return cls(shape, centre, mass, **settings)

    @property
    def local(self):
        """The polygon's corners in local space (px), centred on (0, 0); [] for a circle."""
        return self.shape.points if self.shape.kind == "polygon" else []

    @property
    def radius(self):
        """The circle's radius, or the polygon's bounding radius (px)."""
        return self.shape.radius

    @property
    def is_static(self):
        """True when inv_mass is 0: the body never moves."""
        return self.inv_mass == 0

    def world_points(self):
        """Corners in world space (px): pos + p rotated by angle, for each local corner p.

        A WorldPoints list (shapes.py): a list that remembers its edge normals once computed.
        """
        return WorldPoints([self.pos + p.rotate_rad(self.angle) for p in self.local])

    def point_velocity(self, point):
        """Velocity (px/s) of the world point on this body: vel + omega × (point - pos)."""
        return self.vel + spin_velocity(self.omega, point - self.pos)

    def aabb(self, points=None):
        """Axis-aligned bounding box (left, top, right, bottom) in px; pass world_points() to reuse them."""
        if self.shape.kind == "circle":
            r = self.shape.radius
            return (self.pos.x - r, self.pos.y - r, self.pos.x + r, self.pos.y + r)
        pts = points if points is not None else self.world_points()
        xs = [p.x for p in pts]
        ys = [p.y for p in pts]
        return (min(xs), min(ys), max(xs), max(ys))

    def kinetic_energy(self):
        """½ m |v|² + ½ I ω² (mass·px²/s²); 0 for static bodies.

        A body that does not spin has no spin energy, even with an infinite
        inertia (inv_inertia 0: a body that cannot turn), where I ω² would be NaN.
        """
        if self.inv_mass == 0:
            return 0.0
        spin = 0.5 * self.inertia * self.omega ** 2 if self.omega else 0.0
        return 0.5 * self.mass * self.vel.length_squared() + spin

    def is_finite(self):
        """True when position, velocity, angle and omega are all finite numbers."""
        return all(math.isfinite(v) for v in (self.pos.x, self.pos.y, self.vel.x, self.vel.y,
                                              self.angle, self.omega))

    def __repr__(self):
        return (f"Body({self.shape.kind}, pos=({self.pos.x:.2f}, {self.pos.y:.2f}), "
                f"angle={self.angle:.3f}, mass={self.mass:g})")
