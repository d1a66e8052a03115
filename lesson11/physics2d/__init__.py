"""physics2d: the Lesson 11 rigid-body physics, one concept per module.

    vectors    cross, spin_velocity, input checks
    shapes     box_points, regular_polygon, convex_polygon, polygon_inertia, Polygon, Circle
    bodies     Body
    collision  sat, inside, circle_polygon, circle_circle, contact points (circle_contact_point), circle_toi,
               collide (the shape-pair dispatch) returning a Manifold
    response   apply_impulse, resolve, separate
    arbiter    the reference ("accumulated") solver: accumulated impulses, soft contacts, sub-steps
    world      World (fixed step, solver iterations, declared effects); GRAVITY and STEP, its defaults
    settings   Setting: the attributes of Body and World checked whenever they are set
    sleep      the "sleep" effect: sleep timers, islands falling asleep together, waking
    draw       debug drawing with pygame

Units: px, s, rad; y grows downward; a positive angle turns clockwise on screen.
"""
from .bodies import Body
from .collision import (TOUCH_TOLERANCE, Manifold, center_of, centre_of, circle_circle, circle_contact_point,
                        circle_polygon, circle_polygon_toi, circle_toi, clip_contact_points, closest_on_segment,
                        collide, contact_points, corner_manifold, edge_normals, inside, orient_a_to_b, project, sat)
from .response import (PERCENT, RESTING_SPEED, SLOP, apply_impulse, effective_mass_inverse,
                       relative_velocity, resolve, separate)
from .shapes import (Circle, Polygon, box_points, convex_polygon, polygon_area, polygon_centroid,
                     polygon_inertia, regular_polygon)
from .vectors import Vector2, cross, spin_velocity
from .world import EFFECTS, GRAVITY, LESSON_EFFECTS, STEP, Contact, World
