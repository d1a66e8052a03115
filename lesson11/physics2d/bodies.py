"""Rigid bodies: a shape with a position, an angle, a mass and how it moves.

A body moves with `vel` (px/s) and turns with `omega` (rad/s). Mass 0 means
static: inv_mass = inv_inertia = 0, so no impulse or push can move or turn it.
"""
import math

from .shapes import Circle, Polygon, WorldPoints
from .vectors import Vector2, finite_number, finite_vector, spin_velocity


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
    passes it here. It must be a finite number > 0, and only a dynamic body
    (mass > 0) takes one.
    """

    def __init__(self, shape, pos=(0, 0), mass=1.0, angle=0.0, vel=(0, 0), omega=0.0,
                 restitution=0.2, friction=0.6, color=(200, 150, 90), bullet=False, inertia=None):
        if not isinstance(shape, (Polygon, Circle)):
            shape = Polygon(shape)
        self.shape = shape
        self.pos = finite_vector(pos, "body position")
        self.vel = finite_vector(vel, "body velocity")
        self.angle = finite_number(angle, "body angle")
        self.omega = finite_number(omega, "body omega")
        mass = finite_number(mass, "body mass")
        if mass < 0:
            raise ValueError(f"body mass must be >= 0 (0 means static), got {mass}")
        self.restitution = finite_number(restitution, "body restitution")
        if not 0 <= self.restitution <= 1:
            raise ValueError(f"body restitution must be between 0 and 1, got {self.restitution}")
        self.friction = finite_number(friction, "body friction")
        if self.friction < 0:
            raise ValueError(f"body friction must be >= 0, got {self.friction}")
        self.color = color
        self.bullet = bool(bullet)
        self.asleep = False    # "sleep" effect: a sleeping body is not integrated (World.update_sleep)
        self.sleep_time = 0.0  # s its speed and spin have stayed under the world's sleep thresholds
        self.mass = mass
        if inertia is not None:
            inertia = finite_number(inertia, "body inertia")
            if mass == 0:
                raise ValueError(f"a static body (mass 0) takes no inertia, got inertia={inertia}")
            if inertia <= 0:
                raise ValueError(f"body inertia must be > 0 (mass·px²), got {inertia}")
        if mass == 0:  # static: infinite mass and inertia
            self.inv_mass = self.inv_inertia = 0.0
            self.inertia = 0.0
        else:
            self.inertia = shape.inertia(mass) if inertia is None else inertia
            if not (0 < self.inertia < math.inf and 1 / mass < math.inf and 1 / self.inertia < math.inf):
                raise ValueError(f"body mass {mass:g} with this shape gives a moment of inertia of {self.inertia:g}, "
                                 "too small or too large to invert; use a mass and size nearer 1")
            self.inv_mass = 1 / mass
            self.inv_inertia = 1 / self.inertia

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
