/*
 * HelloFigure4: the model of Figure 4 in "Fast audio-haptic prototyping with
 * mass-interaction physics" (Leonard & Villeneuve), drawn from the side.
 *
 * One mass hangs between two fixed points (grounds) on two spring-dampers.
 * The springs are stretched and not equally stiff, so the mass swings left and
 * right around its balance point; it was also thrown upward at the start, so it
 * bobs up and down as well.
 *
 * Keys: SPACE gives the mass a random kick, R puts it back where it started.
 *
 * Units: ALGO_UNITS, the paper's choice. Stiffness and damping are "per step"
 * numbers; positions are in model units (here 1 unit = 200 pixels).
 */

import tactus.*;

PhysicalModel mdl;
int simRate = 300;   // physics steps per second
int dispRate = 60;   // frames per second
double m = 100;      // inertia of the mass
double dist = 1.5;   // the grounds are at x = +dist and x = -dist
float zoom = 200;    // pixels per model unit

void setup() {
  size(800, 450);
  frameRate(dispRate);

  mdl = new PhysicalModel(simRate, dispRate, paramSystem.ALGO_UNITS);

  /* Create a mass, connected to fixed points via Spring Dampers */
  mdl.addMass3D("mass", m, new Vect3D(0., 0., 0.), new Vect3D(0., 0., 1.));

  mdl.addGround3D("ground1", new Vect3D(dist, 0., 0.));
  mdl.addGround3D("ground2", new Vect3D(-dist, 0., 0.));

  // name, rest length, stiffness K, damping Z, first mass, second mass
  mdl.addSpringDamper3D("spring1", 1., 0.1, 0.01, "mass", "ground1");
  mdl.addSpringDamper3D("spring2", 1., 0.15, 0.01, "mass", "ground2");

  mdl.init();
}

void draw() {
  /* Calculate Physics: simRate / dispRate = 5 steps per frame */
  mdl.draw_physics();

  /* Get the position of the "mass" module */
  PVector pos = mdl.getMatPVector("mass");
  PVector g1 = mdl.getMatPVector("ground1");
  PVector g2 = mdl.getMatPVector("ground2");

  background(250);
  drawHelp();

  // Side view: model x to the right, model z up, origin in the middle.
  translate(width / 2, height / 2);
  drawSpring(g1, pos, mdl.getLinkElongation("spring1"));
  drawSpring(g2, pos, mdl.getLinkElongation("spring2"));
  drawGround(g1);
  drawGround(g2);

  noStroke();
  fill(40, 110, 220);
  ellipse(sx(pos), sy(pos), 36, 36);
}

// Screen coordinates of a model position, seen from the side.
float sx(PVector p) {
  return p.x * zoom;
}

float sy(PVector p) {
  return -p.z * zoom;
}

// A spring drawn as a line: red when stretched, blue when compressed.
void drawSpring(PVector a, PVector b, double elongation) {
  float e = constrain((float) elongation * 2, -1, 1);
  stroke(e > 0 ? 220 : 80, 80, e > 0 ? 80 : 220, 120 + 135 * abs(e));
  strokeWeight(3);
  line(sx(a), sy(a), sx(b), sy(b));
}

void drawGround(PVector g) {
  noStroke();
  fill(60);
  rectMode(CENTER);
  rect(sx(g), sy(g), 16, 16);
}

void drawHelp() {
  fill(30);
  textSize(14);
  text("Figure 4: one Mass3D between two Ground3D (side view, ALGO_UNITS)", 16, 24);
  text("SPACE: kick the mass    R: start again", 16, 44);
  text(String.format("time %.1f s    total energy %.5f (algorithmic units)",
    mdl.getStepCount() / (float) simRate, mdl.getTotalEnergy()), 16, height - 16);
}

void keyPressed() {
  if (key == ' ') {
    // A force applied for one step changes the velocity by F / m units per step.
    mdl.triggerForceImpulse("mass", random(-0.5, 0.5), 0, random(-0.5, 0.5));
  }
  if (key == 'r' || key == 'R') {
    mdl.setMatPosition("mass", new Vect3D(0., 0., 0.));
    mdl.setMatVelocity("mass", new Vect3D(0., 0., 1.));
  }
}
