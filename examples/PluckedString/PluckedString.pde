/*
 * PluckedString: pluck a string with the mouse.
 *
 * Like the audio-haptic plucked string of the paper, the string is a row of
 * masses that move in the x-y plane (Mass2DPlane), joined by spring-dampers and
 * held by two fixed points. The mouse drives a plectrum: a HapticInput3D, the
 * same module a Haply device would drive, that follows the mouse smoothly and
 * touches every mass of the string through a Contact3D. Drag it across the
 * string to pluck it; hold it on the string to mute it.
 *
 * The arrow on the plectrum is the force the string pushes back with: the force
 * a haptic device would make you feel.
 *
 * Keys: R straightens the string.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel. The string is slow on purpose
 * (about 2 Hz) so that you can watch its waves travel; at audio rate the same
 * model would sing.
 */

import tactus.*;

PhysicalModel mdl;
int simRate = 1000;      // steps per second, a typical haptic rate
int nMasses = 50;        // masses of the string
float spacing = 12;      // pixels between neighbouring masses
float restLength = 1;    // spring rest length: much shorter than the spacing, so the string is taut
float stiffness = 0.05;  // spring stiffness, per step squared
float damping = 0.001;   // spring damping, per step
float pickRadius = 14;   // size of the plectrum, pixels
float left, top;         // where the string starts on screen

void setup() {
  size(800, 400);
  frameRate(60);
  left = (width - spacing * (nMasses + 1)) / 2;
  top = height / 2;

  mdl = new PhysicalModel(simRate, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0005);   // air friction: the string rings for a few seconds

  mdl.addGround3D("left", new Vect3D(left, top, 0));
  for (int i = 0; i < nMasses; i++) {
    mdl.addMass2DPlane("str" + i, 1.0, new Vect3D(left + spacing * (i + 1), top, 0), new Vect3D());
  }
  mdl.addGround3D("right", new Vect3D(left + spacing * (nMasses + 1), top, 0));

  mdl.addSpringDamper3D("spring_left", restLength, stiffness, damping, "left", "str0");
  for (int i = 0; i < nMasses - 1; i++) {
    mdl.addSpringDamper3D("spring" + i, restLength, stiffness, damping, "str" + i, "str" + (i + 1));
  }
  mdl.addSpringDamper3D("spring_right", restLength, stiffness, damping, "str" + (nMasses - 1), "right");

  // The plectrum follows the mouse through a smoothing filter of about 20 steps (20 ms).
  mdl.addHapticInput3D("plectrum", new Vect3D(width / 2, 40, 0), 20);
  for (int i = 0; i < nMasses; i++) {
    // name, contact distance, stiffness, damping, first mass, second mass
    mdl.addContact3D("pick" + i, pickRadius, 0.1, 0.01, "plectrum", "str" + i);
  }

  mdl.init();
}

void draw() {
  mdl.setHapticPosition("plectrum", new Vect3D(mouseX, mouseY, 0));
  mdl.draw_physics();
  // The force on the plectrum, added up over the steps of this frame.
  Vect3D force = mdl.getHapticForce("plectrum");

  background(20, 24, 32);

  // The string
  stroke(230, 200, 120);
  strokeWeight(2);
  noFill();
  beginShape();
  PVector p = mdl.getMatPVector("left");
  vertex(p.x, p.y);
  for (int i = 0; i < nMasses; i++) {
    p = mdl.getMatPVector("str" + i);
    vertex(p.x, p.y);
  }
  p = mdl.getMatPVector("right");
  vertex(p.x, p.y);
  endShape();

  noStroke();
  fill(255, 230, 160);
  for (int i = 0; i < nMasses; i++) {
    p = mdl.getMatPVector("str" + i);
    ellipse(p.x, p.y, 5, 5);
  }

  // The plectrum and the force it receives
  PVector pick = mdl.getMatPVector("plectrum");
  fill(220, 70, 70, 160);
  ellipse(pick.x, pick.y, 2 * pickRadius, 2 * pickRadius);
  stroke(255, 120, 120);
  strokeWeight(2);
  float arrow = 20;   // pixels per unit of force
  line(pick.x, pick.y, pick.x + (float) force.x * arrow, pick.y + (float) force.y * arrow);

  fill(200);
  textSize(14);
  text("Drag the red plectrum across the string to pluck it.  R: straighten the string", 16, 24);
  text(String.format("force on the plectrum: %.4f (per frame)", Math.sqrt(force.x * force.x + force.y * force.y)),
    16, height - 16);
}

void keyPressed() {
  if (key == 'r' || key == 'R') {
    for (int i = 0; i < nMasses; i++) {
      mdl.setMatPosition("str" + i, new Vect3D(left + spacing * (i + 1), top, 0));
    }
  }
}
