/*
 * Rope: a rope with a weight at its end, swung along a figure of eight by a
 * velocity-controlled hand, catches on three pegs; let go of it, and it falls to
 * the floor. The sketch reads all the rope's positions and speeds at once into
 * lists (the paper engine's ArrayList<PVector> helpers) and colours the rope by
 * speed.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y points up.
 */

import tactus.*;

PhysicalModel mdl;
int simRate = 1000;
int dispRate = 60;
int nLinks = 30;
float segment = 10;
boolean holding = true;   // key SPACE lets go, R starts again
int hand;                 // index of the hand mass
Vect3D target = new Vect3D();  // where the hand is heading

ArrayList<PVector> ropePos = new ArrayList<PVector>();
ArrayList<PVector> ropeSpeed = new ArrayList<PVector>();  // displacement per step
ArrayList<PVector> pegs = new ArrayList<PVector>();
ArrayList<PVector> fastPos = new ArrayList<PVector>();
ArrayList<PVector> fastSpeed = new ArrayList<PVector>();
float fastest = 0;        // px/s, refreshed four times a second

void setup() {
  size(900, 560);
  frameRate(dispRate);
  build();
}

void build() {
  mdl = new PhysicalModel(simRate, dispRate);
  mdl.setGravityDirection(new PVector(0, 1, 0));
  mdl.setGravity(0.0004);
  mdl.setFriction(0.001);
  mdl.addGround3D("peg0", new Vect3D(270, 230, 0));
  mdl.addGround3D("peg1", new Vect3D(450, 130, 0));
  mdl.addGround3D("peg2", new Vect3D(630, 230, 0));
  // The hand, then the rope hanging from it, then the weight at the end.
  mdl.addMass3D("hand", 1, new Vect3D(450, 480, 0), new Vect3D(0, 0, 0));
  mdl.addPlaneContact("floor", 5, 0.1, 0.005, 1, 30, "hand");
  for (int i = 1; i <= nLinks; i++) {
    String name = i == nLinks ? "weight" : "knot" + i;
    mdl.addMass3D(name, i == nLinks ? 3 : 1, new Vect3D(450, 480 - segment * i, 0), new Vect3D(0, 0, 0));
    mdl.addRope3D("rope" + i, segment, 0.2, 0.05, i == 1 ? "hand" : "knot" + (i - 1), name);
    for (int p = 0; p < 3; p++) {
      mdl.addContact3D("catch", 14, 0.1, 0.002, "peg" + p, name);
    }
    mdl.addPlaneContact("floor", 5, 0.1, 0.005, 1, 30, name);
  }
  mdl.init();
  hand = mdl.getMatIndex("hand");
  holding = true;
  // Fill the lists once; later frames only update them.
  mdl.createPosSpeedArraysForModType(ropePos, ropeSpeed, matModuleType.Mass3D);
  mdl.getAllMatsOfType(pegs, matModuleType.Ground3D);
}

void draw() {
  float t = frameCount / (float) dispRate;
  if (holding) {
    // Steer the hand's velocity along a figure of eight (velocity control ignores forces).
    float w = TWO_PI / 5;
    float tx = 450 + 200 * sin(w * t);
    float ty = 480 + 40 * sin(2 * w * t);
    target.set(tx, ty, 0);
    Vect3D p = mdl.getMatPosAt(hand);
    float vx = 200 * w * cos(w * t) + 5 * (float) (target.x() - p.x());
    float vy = 80 * w * cos(2 * w * t) + 5 * (float) (target.y() - p.y());
    mdl.triggerVelocityControl(hand, vx, vy, 0);
  }
  mdl.draw_physics();
  mdl.updatePosSpeedArraysForModType(ropePos, ropeSpeed, matModuleType.Mass3D);
  if (frameCount % 15 == 0) {
    // The older helper does the same in one call, clearing and refilling both lists.
    mdl.getAllMatSpeedsOfType(fastPos, fastSpeed, matModuleType.Mass3D);
    fastest = 0;
    for (PVector v : fastSpeed) {
      fastest = max(fastest, v.mag() * simRate);
    }
  }

  background(250);
  noStroke();
  fill(225, 215, 200);
  rect(0, height - 30, width, 30);   // the floor
  noStroke();
  fill(60);
  for (PVector p : pegs) {
    ellipse(p.x, height - p.y, 16, 16);
  }
  // The rope: one segment per link, coloured by the speed of its lower end.
  strokeWeight(6);
  for (int i = 1; i < ropePos.size(); i++) {
    PVector a = ropePos.get(i - 1);
    PVector b = ropePos.get(i);
    float speed = ropeSpeed.get(i).mag() * simRate;   // px/s
    stroke(lerpColor(color(60, 90, 160), color(240, 120, 20), constrain(speed / 800, 0, 1)));
    line(a.x, height - a.y, b.x, height - b.y);
  }
  strokeWeight(1);
  noStroke();
  PVector w = ropePos.get(ropePos.size() - 1);
  fill(120, 40, 40);
  ellipse(w.x, height - w.y, 22, 22);
  PVector h = ropePos.get(0);
  fill(holding ? color(220, 40, 40) : color(200));
  ellipse(h.x, height - h.y, 18, 18);

  fill(20);
  textSize(13);
  textAlign(LEFT, TOP);
  text("fastest point of the rope: " + nf(fastest, 0, 0) + " px/s", 12, 10);
  text("SPACE: " + (holding ? "let go" : "(the hand has let go)") + "   R: start again", 12, height - 22);
}

void keyPressed() {
  if (key == ' ' && holding) {
    holding = false;
    mdl.stopVelocityControl("hand");   // the hand keeps its last velocity and falls with the rope
  } else if (key == 'r' || key == 'R') {
    build();
  }
}
