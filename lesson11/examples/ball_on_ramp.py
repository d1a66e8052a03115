"""A ball of radius 12 px sunk into a static triangle ramp, then pushed out.

circle_polygon (lesson11/physics2d/collision.py) finds the point of the
ramp's outline closest to the ball's centre; the normal points from the
centre towards it and the depth is radius - distance. separate
(lesson11/physics2d/response.py) then moves the bodies apart by the depth,
split by inverse mass: the ramp is static (inverse mass 0), so the ball,
mass 2, moves the whole way. slop=0 and percent=1 remove the full overlap
at once (the World uses a gentler 0.5 px and 40 % per pass).

After the push the ball touches the ramp exactly. physics2d counts exact
touching as apart (overlaps up to TOUCH_TOLERANCE = 1e-6 px), so this prints
"apart"; the lesson's own listing printed "depth 0.000 px" here.

Run: python -m lesson11.examples.ball_on_ramp
"""
from lesson11.physics2d import Body, Circle, circle_polygon, separate

RAMP_CORNERS = [(0, 100), (200, 40), (200, 100)]  # world px, a static triangle
BALL_CENTRE = (100, 62)
BALL_RADIUS = 12
BALL_MASS = 2


def main():
    ramp = Body.from_world_points(RAMP_CORNERS, mass=0)
    ball = Body(Circle(BALL_RADIUS), BALL_CENTRE, BALL_MASS)
    normal, depth = circle_polygon(ball.pos, ball.radius, ramp.world_points())
    print(f"normal ({normal.x:.2f}, {normal.y:.2f}), depth {depth:.2f} px")
    separate(ball, ramp, normal, depth, slop=0, percent=1)  # ball is A, the normal points A -> B
    hit = circle_polygon(ball.pos, ball.radius, ramp.world_points())
    print("after the push:", "apart" if hit is None else f"depth {hit[1]:.3f} px")
    print(f"ball moved to ({ball.pos.x:.2f}, {ball.pos.y:.2f}); the static ramp stayed at "
          f"({ramp.pos.x:.2f}, {ramp.pos.y:.2f})")


if __name__ == "__main__":
    main()
