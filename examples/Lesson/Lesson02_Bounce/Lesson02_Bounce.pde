/*
 * Lesson02_Bounce: step 2 of the classroom lesson (docs/classroom.md).
 *
 * The falling mass of step 1 now lands on a floor. The floor is an interaction, a PlaneContact3D:
 * while the ball is closer to the plane than its radius, a spring (stiffness K) and a damper (Z)
 * push it back. A stiff floor bounces quickly, a soft one sinks in; the damper takes energy away.
 *
 * Keys: SPACE throws the ball again, UP / DOWN make the floor stiffer or softer,
 *       LEFT / RIGHT take more or less energy away at each bounce (the damping Z).
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y up (the drawing flips it).
 */

import tactus.*;

PhysicalModel mdl;
float radius = 12;       // the ball's radius, pixels
float floorY = 40;       // where the floor is, pixels above the bottom of the window
float K = 0.05;          // the floor's stiffness, per step²
float Z = 0.001;         // the floor's damping, per step

void setup() {
  size(600, 400);
  frameRate(60);

  mdl = new PhysicalModel(1000, 60);
  mdl.setGravityDirection(new Vect3D(0, 1, 0));
  mdl.setGravity(0.0005);
  mdl.addMass3D("ball", 1, new Vect3D(40, 300, 0), new Vect3D(130, 0, 0));

  // name, distance (the ball's radius), K, Z, axis (0 = x, 1 = y, 2 = z), where the plane is, which mass
  mdl.addPlaneContact("floor", radius, K, Z, 1, floorY, "ball");
  mdl.init();
}

void draw() {
  mdl.draw_physics();
  PVector p = mdl.getMatPVector("ball");
  if (p.x > width + 20) {
    throwBall();
  }

  background(245);
  pushMatrix();
  translate(0, height);
  scale(1, -1);
  stroke(90);
  strokeWeight(2);
  line(0, floorY, width, floorY);
  noStroke();
  fill(40, 110, 220);
  ellipse(p.x, p.y, 2 * radius, 2 * radius);
  popMatrix();

  fill(30);
  textSize(14);
  text("Step 2: bounce.   SPACE: throw again   UP/DOWN: floor stiffness   LEFT/RIGHT: damping", 12, 22);
  // energy: motion plus height, in the model's own units (mass x pixels² per step²)
  text(String.format("K %.4f   Z %.5f   energy %.4f", K, Z, mdl.getTotalEnergy()), 12, 42);
}

void throwBall() {
  mdl.setMatPosition("ball", new Vect3D(40, 300, 0));
  mdl.setMatVelocity("ball", new Vect3D(130, 0, 0));
}

void keyPressed() {
  if (key == ' ') {
    throwBall();
  } else if (keyCode == UP || keyCode == DOWN) {
    K = constrain(K * (keyCode == UP ? 2 : 0.5), 0.0005, 1);
    mdl.setLinkStiffness("floor", K);
  } else if (keyCode == LEFT || keyCode == RIGHT) {
    Z = constrain(Z * (keyCode == RIGHT ? 2 : 0.5), 0.00001, 0.1);
    mdl.setLinkDamping("floor", Z);
  }
}
