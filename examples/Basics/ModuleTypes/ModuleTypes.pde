/*
 * ModuleTypes: one model with every kind of mass and every kind of interaction
 * of the paper's engine, drawn by your own code, which asks the model what each
 * module is (getMatTypeAt, getLinkTypeAt) and switches on the answer. The info
 * line walks through the links one by one and names both ends of each.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y points up (the floor is a plane
 * at y = 40, which pushes toward +y).
 */

import tactus.*;

PhysicalModel mdl;
int simRate = 1000;
int dispRate = 60;
float gravity = 0.0005;     // per step squared
int gravityTurns = 0;       // quarter turns of the gravity direction, key G
boolean showForces = true;  // key F
int shownLink = 0;          // the link named on the info line
boolean handByMouse = false;

void setup() {
  size(960, 600);
  frameRate(dispRate);
  mdl = new PhysicalModel(simRate, dispRate);

  // A spring pendulum: a Mass3D on a stiff SpringDamper3D, thrown sideways.
  mdl.addGround3D("pivot", new Vect3D(100, 480, 0));
  mdl.addMass3D("bob", 1, new Vect3D(100, 380, 0), new Vect3D(150, 0, 0));
  mdl.addSpringDamper3D("rod", 100, 0.01, 0.0005, "pivot", "bob");

  // A box that stays in its plane (Mass2DPlane), on a Spring3D and a Damper3D side by side.
  mdl.addGround3D("hook", new Vect3D(230, 480, 0));
  mdl.addMass2DPlane("box", 1, new Vect3D(230, 340, 0), new Vect3D(0, 0, 0));
  mdl.addSpring3D("coil", 80, 0.0003, "hook", "box");
  mdl.addDamper3D("dashpot", 0.0003, "hook", "box");

  // A weight on a Rope3D: pulls only when stretched. It is thrown upward, so the rope goes slack.
  mdl.addGround3D("nail", new Vect3D(360, 480, 0));
  mdl.addMass3D("weight", 1, new Vect3D(360, 400, 0), new Vect3D(0, 150, 0));
  mdl.addRope3D("cord", 120, 0.01, 0.001, "nail", "weight");

  // A 3D oscillator: a mass tied to its own rest point.
  mdl.addOsc3D("tuning", 1, 0.0004, 0.00002, new Vect3D(490, 400, 0), new Vect3D(0, 600, 0));

  // The 1D modules move along z only; they are drawn with z upward beside their x, y.
  mdl.addGround1D("base1D", new Vect3D(600, 400, 0));
  mdl.addMass1D("piston", 1, new Vect3D(600, 400, 0), new Vect3D(0, 0, 800));
  mdl.addSpringDamper1D("shock", 0, 0.0006, 0.00001, "base1D", "piston");
  mdl.addOsc1D("reed", 1, 0.0009, 0.00001, new Vect3D(680, 400, 0), new Vect3D(0, 0, 800));

  // A moon that ignores gravity and air friction (Mass3DSimple), held in orbit by an inverse-square
  // Attractor3D. Circular orbit: v^2 / r = A / (m r^2), so A = m r v^2 (v per step).
  float r = 80;
  float v = 0.168;  // units per step: about 3 s per turn
  mdl.addGround3D("sun", new Vect3D(850, 400, 0));
  mdl.addMass3DSimple("moon", 1, new Vect3D(850 + r, 400, 0), new Vect3D(0, v * simRate, 0));
  mdl.addAttractor3D("pull", 10, r * v * v, "sun", "moon");

  // Marbles kept in a Bubble3D, touching each other through Contact3D, stirred by a hand.
  mdl.addGround3D("centre", new Vect3D(250, 170, 0));
  int nMarbles = 6;
  for (int i = 0; i < nMarbles; i++) {
    float a = TWO_PI * i / nMarbles;
    mdl.addMass3D("marble" + i, 1, new Vect3D(250 + 50 * cos(a), 170 + 50 * sin(a), 0), new Vect3D(0, 0, 0));
    mdl.addBubble3D("skin" + i, 100, 0.05, 0.002, "centre", "marble" + i);
  }
  for (int i = 0; i < nMarbles; i++) {
    for (int j = i + 1; j < nMarbles; j++) {
      mdl.addContact3D("touch", 24, 0.05, 0.002, "marble" + i, "marble" + j);
    }
  }
  mdl.addHapticInput3D("hand", new Vect3D(250, 170, 0), 20);
  for (int i = 0; i < nMarbles; i++) {
    mdl.addContact3D("stir", 26, 0.05, 0.002, "hand", "marble" + i);
  }

  // Balls dropped on a floor: a PlaneContact3D across the y axis at y = 40, one per ball.
  for (int i = 0; i < 3; i++) {
    mdl.addMass3D("ball" + i, 1, new Vect3D(560 + 110 * i, 200 + 60 * i, 0), new Vect3D(0, 0, 0));
    mdl.addPlaneContact("floor", 12, 0.05, 0.001, 1, 40, "ball" + i);
  }

  mdl.setFriction(0.00002);
  applyGravity();
  mdl.init();
}

// Gravity pulls along -direction, so the direction (0, 1, 0) pulls down the screen.
void applyGravity() {
  float a = HALF_PI * gravityTurns;
  mdl.setGravityDirection(new PVector(sin(a), cos(a), 0));
  mdl.setGravity(gravity);
}

void draw() {
  // The hand circles inside the bubble on its own; with the mouse pressed it follows the mouse.
  float t = frameCount / (float) dispRate;
  Vect3D hand = handByMouse
    ? new Vect3D(mouseX, height - mouseY, 0)
    : new Vect3D(250 + 55 * cos(t * 1.6), 170 + 55 * sin(t * 1.6), 0);
  mdl.setHapticPosition("hand", hand);
  mdl.draw_physics();
  mdl.getHapticForce("hand"); // read (and clear) the force the hand would feel

  background(245);
  if (frameCount % 30 == 0) {
    shownLink = (shownLink + 1) % mdl.getNumberOfLinks();
  }
  for (int i = 0; i < mdl.getNumberOfLinks(); i++) {
    drawLink(i, i == shownLink);
  }
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    drawMat(i);
  }
  drawInfo();
}

// Model to screen: y up in the model, down on the screen. 1D modules show their z as height.
float sx(Vect3D p) {
  return (float) p.x();
}
float sy(Vect3D p) {
  return height - (float) p.y();
}

void drawMat(int i) {
  Vect3D p = mdl.getMatPosAt(i);
  Vect3D before = mdl.getMatDelayedPosAt(i); // where it was one step ago
  float x = sx(p);
  float y = sy(p);
  matModuleType type = mdl.getMatTypeAt(i);
  switch (type) {
  case Mass1D:
  case Osc1D:
    y -= (float) p.z();
    stroke(150);
    line(x, sy(p) - 60, x, sy(p) + 60); // its track
    noStroke();
    fill(type == matModuleType.Mass1D ? color(60, 110, 200) : color(130, 80, 200));
    ellipse(x, y, 18, 18);
    break;
  case Mass3D:
    noStroke();
    fill(210, 120, 30);
    ellipse(x, y, 20, 20);
    break;
  case Mass2DPlane:
    noStroke();
    fill(40, 150, 110);
    rectMode(CENTER);
    rect(x, y, 22, 22);
    break;
  case Osc3D:
    // the rest point is where the oscillator started; the ring shows how far it is from it
    noFill();
    stroke(130, 80, 200);
    float d = (float) mdl.getOsc3DDeltaPos(i);
    ellipse(x, y, 2 * d + 4, 2 * d + 4);
    noStroke();
    fill(130, 80, 200);
    ellipse(x, y, 14, 14);
    break;
  case Mass3DSimple:
    stroke(40);
    fill(255);
    ellipse(x, y, 16, 16);
    break;
  case Ground3D:
  case Ground1D:
    noStroke();
    fill(70);
    rectMode(CENTER);
    rect(x, y, 10, 10);
    break;
  case HapticInput3D:
    noFill();
    stroke(220, 40, 40);
    strokeWeight(2);
    ellipse(x, y, 28, 28);
    strokeWeight(1);
    break;
  default:
    return;
  }
  // Motion streak: the displacement of the last step, times 25.
  if (type != matModuleType.Ground3D && type != matModuleType.Ground1D) {
    stroke(0, 90);
    float dx = (float) (p.x() - before.x());
    float dy = (float) (p.y() - before.y());
    if (type == matModuleType.Mass1D || type == matModuleType.Osc1D) {
      dy = (float) (p.z() - before.z());
      dx = 0;
    }
    line(x, y, x - 25 * dx, y + 25 * dy);
  }
  // The force the mass will feel at the next step, for the free 3D masses.
  if (showForces && type == matModuleType.Mass3D) {
    PVector f = mdl.getMatForcePVector(i);
    stroke(200, 0, 0);
    line(x, y, x + constrain(4000 * f.x, -60, 60), y - constrain(4000 * f.y, -60, 60));
  }
}

void drawLink(int i, boolean highlight) {
  Vect3D a = mdl.getLinkPos1At(i);
  Vect3D b = mdl.getLinkPos2At(i);
  strokeWeight(highlight ? 4 : 1.5);
  switch (mdl.getLinkTypeAt(i)) {
  case Spring3D:
    stroke(30, 100, 100);
    line(sx(a) - 5, sy(a), sx(b) - 5, sy(b));
    break;
  case Damper3D:
    stroke(160);
    line(sx(a) + 5, sy(a), sx(b) + 5, sy(b));
    break;
  case SpringDamper3D:
    stroke(30, 120, 220);
    line(sx(a), sy(a), sx(b), sy(b));
    break;
  case SpringDamper1D:
    stroke(60, 110, 200);
    line(sx(a) - 8, sy(a) - (float) a.z(), sx(b) - 8, sy(b) - (float) b.z());
    break;
  case Rope3D:
    // green when slack, red when it pulls
    stroke(mdl.getLinkElongationAt(i) > 0 ? color(220, 40, 40) : color(40, 170, 80));
    line(sx(a), sy(a), sx(b), sy(b));
    break;
  case Contact3D:
    // drawn only while the two masses touch
    if (mdl.getLinkDistanceAt(i) < mdl.getLinkDRestAt(i) || highlight) {
      stroke(220, 120, 0);
      line(sx(a), sy(a), sx(b), sy(b));
    }
    break;
  case Bubble3D:
    noFill();
    stroke(120, 160, 200, highlight ? 255 : 60);
    float rad = (float) mdl.getLinkDRestAt(i);
    ellipse(sx(a), sy(a), 2 * rad + 20, 2 * rad + 20);
    break;
  case PlaneContact3D:
    // the plane itself, from what the link says about it
    stroke(80);
    float pos = (float) mdl.getPlanePositionAt(i);
    if (mdl.getPlaneOrientationAt(i) == 1) {
      line(520, height - pos, 940, height - pos);
    } else if (mdl.getPlaneOrientationAt(i) == 0) {
      line(pos, height - 60, pos, height - 520);
    }
    if (highlight) {
      stroke(220, 120, 0);
      line(sx(a), sy(a), sx(b), sy(b)); // end 2 is the foot of the ball on the plane
    }
    break;
  case Attractor3D:
    stroke(200, 170, 0, highlight ? 255 : 90);
    line(sx(a), sy(a), sx(b), sy(b));
    break;
  default:
    break;
  }
  strokeWeight(1);
}

void drawInfo() {
  fill(20);
  textSize(13);
  textAlign(LEFT, TOP);
  int i = shownLink;
  int m1 = mdl.getLinkMat1IdxAt(i);
  int m2 = mdl.getLinkMat2IdxAt(i);
  String end2 = m2 < 0 ? "a plane" : "mat " + m2 + " '" + mdl.getLinkMat2NameAt(i) + "' (" + mdl.getMatTypeAt(m2) + ")";
  text("link " + i + " of " + mdl.getNumberOfLinks() + ": " + mdl.getLinkTypeAt(i) + " '" + mdl.getLinkNameAt(i)
    + "' joins mat " + m1 + " '" + mdl.getLinkMat1NameAt(i) + "' (" + mdl.getMatTypeAt(m1) + ") and " + end2, 12, 10);
  PVector pull = mdl.getMatForcePVector("bob");
  text(mdl.getNumberOfMats() + " masses of 9 kinds, " + mdl.getNumberOfLinks() + " links of 9 kinds; the rod pulls the bob with "
    + nf(pull.mag() * 1000, 0, 3) + " thousandths of a unit", 12, 28);
  text("G: turn gravity (now " + (90 * (gravityTurns % 4)) + " deg)   K: kick everything   F: force arrows "
    + (showForces ? "on" : "off") + "   L: next link   hold the mouse: the hand follows it", 12, height - 22);
}

void keyPressed() {
  if (key == 'g' || key == 'G') {
    gravityTurns++;
    applyGravity();
  } else if (key == 'k' || key == 'K') {
    for (int i = 0; i < mdl.getNumberOfMats(); i++) {
      if (mdl.getMatTypeAt(i) != matModuleType.Ground3D && mdl.getMatTypeAt(i) != matModuleType.Ground1D
        && mdl.getMatTypeAt(i) != matModuleType.HapticInput3D) {
        mdl.triggerForceImpulse(i, random(-0.2, 0.2), random(0, 0.3), random(-0.2, 0.2));
      }
    }
  } else if (key == 'f' || key == 'F') {
    showForces = !showForces;
  } else if (key == 'l' || key == 'L') {
    shownLink = (shownLink + 1) % mdl.getNumberOfLinks();
  }
}

void mousePressed() {
  handByMouse = true;
}

void mouseReleased() {
  handByMouse = false;
}
