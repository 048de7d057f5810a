/*
 * Lesson03_Spring: step 3 of the classroom lesson (docs/classroom.md).
 *
 * A mass hangs from a fixed point (a Ground3D) on a spring with a damper (a SpringDamper3D). Pulled
 * away and let go, it swings and bounces. A mass M on a spring K, at fs steps per second, rings at
 * about f = fs / (2 pi) * sqrt(K / M) hertz: the heavier, the slower; the stiffer, the faster. The
 * scheme stays stable only while K / M is below 4 (init() warns if it is not).
 *
 * Mouse: drag the mass, let go to release it.  Keys: UP / DOWN stiffer or softer spring.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y up (the drawing flips it).
 */

import tactus.*;

PhysicalModel mdl;
float M = 1;            // the mass
float K = 0.0002;       // the spring's stiffness, per step²: f = 1000 / (2 pi) * sqrt(0.0002) = 2.25 Hz
float Z = 0.0001;       // the spring's damping, per step
boolean dragging = false;

void setup() {
  size(600, 400);
  frameRate(60);

  mdl = new PhysicalModel(1000, 60);
  mdl.setGravityDirection(new Vect3D(0, 1, 0));
  mdl.setGravity(0.0005);

  mdl.addGround3D("hook", new Vect3D(300, 320, 0));
  mdl.addMass3D("bob", M, new Vect3D(420, 100, 0), new Vect3D());   // starts pulled down and to the side
  // name, rest length, K, Z, the two ends
  mdl.addSpringDamper3D("spring", 150, K, Z, "hook", "bob");
  mdl.init();
}

void draw() {
  if (dragging) {
    mdl.setMatPosition("bob", new Vect3D(mouseX, height - mouseY, 0));
    mdl.setMatVelocity("bob", new Vect3D());
  }
  mdl.draw_physics();
  PVector hook = mdl.getMatPVector("hook");
  PVector bob = mdl.getMatPVector("bob");

  background(245);
  pushMatrix();
  translate(0, height);
  scale(1, -1);
  float stretch = (float) mdl.getLinkElongation("spring");
  stroke(stretch > 0 ? 220 : 80, 80, stretch > 0 ? 80 : 220);
  strokeWeight(3);
  line(hook.x, hook.y, bob.x, bob.y);
  noStroke();
  fill(60);
  rectMode(CENTER);
  rect(hook.x, hook.y, 16, 16);
  fill(40, 110, 220);
  ellipse(bob.x, bob.y, 30, 30);
  popMatrix();

  fill(30);
  textSize(14);
  text("Step 3: a mass on a spring.   Drag the mass.   UP/DOWN: stiffness", 12, 22);
  text(String.format("K %.5f   K/M %.5f (stable below 4)   f = %.2f Hz", K, K / M,
    1000 / TWO_PI * sqrt(K / M)), 12, 42);
}

void mousePressed() {
  PVector bob = mdl.getMatPVector("bob");
  dragging = dist(mouseX, height - mouseY, bob.x, bob.y) < 40;
}

void mouseReleased() {
  dragging = false;
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    K = constrain(K * (keyCode == UP ? 2 : 0.5), 0.00001, 0.5);
    mdl.setLinkStiffness("spring", K);
  }
}
