/*
 * Lesson01_FallingMass: step 1 of the classroom lesson (docs/classroom.md).
 *
 * One mass thrown up under gravity. Every Tactus sketch has this shape: build the model in setup()
 * (masses, then what links them, then init()), and in draw() step it (draw_physics) and draw it.
 * When the ball has left the window it is thrown again.
 *
 * Keys: SPACE throws the ball again.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel. The model's y axis points up, as in a physics book:
 * the drawing flips it with translate(0, height) and scale(1, -1).
 */

import tactus.*;

PhysicalModel mdl;
PVector[] trail = new PVector[40];   // where the ball was, a point every 3 frames

void setup() {
  size(600, 400);
  frameRate(60);

  mdl = new PhysicalModel(1000, 60);              // 1000 steps per second, drawn at 60 frames per second
  mdl.setGravityDirection(new Vect3D(0, 1, 0));   // "up" is +y
  mdl.setGravity(0.0005);                         // per step²: 0.0005 * 1000 * 1000 = 500 pixels/s²

  // name, mass, where it starts (pixels), its velocity (pixels per second)
  mdl.addMass3D("ball", 1, new Vect3D(80, 50, 0), new Vect3D(120, 500, 0));
  mdl.init();
}

void draw() {
  mdl.draw_physics();                             // 1000 / 60 steps of the model
  PVector p = mdl.getMatPVector("ball");
  if (p.y < -20 || p.x > width + 20) {            // out of the window: throw it again
    throwBall();
  }
  if (frameCount % 3 == 0) {
    System.arraycopy(trail, 0, trail, 1, trail.length - 1);
    trail[0] = p.copy();
  }

  background(245);
  pushMatrix();
  translate(0, height);
  scale(1, -1);                                   // from here on, y points up
  noStroke();
  for (int i = trail.length - 1; i > 0; i--) {
    if (trail[i] != null) {
      fill(40, 110, 220, 150 - 3 * i);
      ellipse(trail[i].x, trail[i].y, 8, 8);
    }
  }
  fill(40, 110, 220);
  ellipse(p.x, p.y, 24, 24);
  popMatrix();

  fill(30);
  textSize(14);
  text("Step 1: a falling mass.   SPACE: throw it again", 12, 22);
  text(String.format("time %.2f s   height %.0f px   speed %.0f px/s", mdl.getStepCount() / 1000.0,
    p.y, mdl.getMatVelocity("ball").norm()), 12, 42);
}

void throwBall() {
  mdl.setMatPosition("ball", new Vect3D(80, 50, 0));
  mdl.setMatVelocity("ball", new Vect3D(120, 500, 0));
}

void keyPressed() {
  if (key == ' ') {
    throwBall();
  }
}
