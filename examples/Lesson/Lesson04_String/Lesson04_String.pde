/*
 * Lesson04_String: step 4 of the classroom lesson (docs/classroom.md).
 *
 * Thirty masses in a row, each tied to its neighbours by a spring, between two fixed points: a string.
 * It is the spring of step 3, thirty times. Its springs are shorter at rest than the gaps between the
 * masses, so the string is taut, and a pluck runs along it as a wave and comes back. It runs slowly
 * here (1000 steps per second) so that you can watch it; step 5 runs it 44 times faster and listens.
 *
 * Mouse: grab the string anywhere, pull, let go.  Keys: SPACE plucks it for you.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y up (the drawing flips it).
 */

import tactus.*;

PhysicalModel mdl;
int masses = 30;        // moving masses of the string
float K = 0.05;         // spring stiffness, per step²
float Z = 0.0005;       // spring damping, per step
float left, right, y;   // where the string is, pixels
float spacing;          // distance between neighbours at rest
int grabbed = -1;       // the mass held by the mouse, or -1
int lastPluck = -10000;

void setup() {
  size(600, 400);
  frameRate(60);
  left = 50;
  right = width - 50;
  y = height / 2;
  spacing = (right - left) / (masses + 1);

  mdl = new PhysicalModel(1000, 60);
  mdl.setFriction(0.001);
  buildString();
  mdl.init();
}

// The string: ground g0, masses m1 .. m30, ground g31, and springs s0 .. s30 between neighbours.
void buildString() {
  mdl.addGround3D("g0", new Vect3D(left, y, 0));
  for (int i = 1; i <= masses; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(left + i * spacing, y, 0), new Vect3D());
  }
  mdl.addGround3D("g" + (masses + 1), new Vect3D(right, y, 0));
  for (int i = 0; i <= masses; i++) {
    // rest length: half the gap, so that the string is taut
    mdl.addSpringDamper3D("s" + i, spacing / 2, K, Z, name(i), name(i + 1));
  }
}

void draw() {
  if (grabbed > 0) {
    mdl.setMatPosition("m" + grabbed, new Vect3D(left + grabbed * spacing, height - mouseY, 0));
  } else if (millis() - lastPluck > 3000) {   // plays on its own until the mouse takes over
    pluck(int(random(3, masses - 2)), 60);
  }
  mdl.draw_physics();

  background(245);
  pushMatrix();
  translate(0, height);
  scale(1, -1);
  stroke(90, 160, 200);
  strokeWeight(2);
  for (int i = 0; i <= masses; i++) {
    PVector a = mdl.getMatPVector(name(i));
    PVector b = mdl.getMatPVector(name(i + 1));
    line(a.x, a.y, b.x, b.y);
  }
  noStroke();
  for (int i = 0; i <= masses + 1; i++) {
    PVector p = mdl.getMatPVector(name(i));
    fill(i == 0 || i == masses + 1 ? 60 : color(230, 150, 40));
    ellipse(p.x, p.y, 10, 10);
  }
  popMatrix();

  fill(30);
  textSize(14);
  text("Step 4: a string, slowed down.   Drag it and let go.   SPACE: pluck", 12, 22);
}

// The name of the i-th point of the string, a ground at both ends.
String name(int i) {
  return i == 0 || i == masses + 1 ? "g" + i : "m" + i;
}

// Lifts the string into a triangle of the given height (pixels) with its top at mass 'at', and lets go.
void pluck(int at, float h) {
  lastPluck = millis();
  for (int i = 1; i <= masses; i++) {
    float lift = i <= at ? h * i / at : h * (masses + 1 - i) / (masses + 1 - at);
    mdl.setMatPosition("m" + i, new Vect3D(left + i * spacing, y + lift, 0));
  }
}

void mousePressed() {
  int i = round((mouseX - left) / spacing);
  grabbed = i >= 1 && i <= masses ? i : -1;
  lastPluck = millis() + 100000;   // the mouse plays now
}

void mouseReleased() {
  grabbed = -1;
}

void keyPressed() {
  if (key == ' ') {
    pluck(int(random(3, masses - 2)), 60);
  }
}
