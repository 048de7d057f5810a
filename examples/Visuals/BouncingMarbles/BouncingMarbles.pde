/*
 * BouncingMarbles: marbles under gravity, inside a round bowl, on a floor.
 *
 * A small version of the paper's "Enclosed Marbles". Each marble is a
 * Mass2DPlane (it moves in the x-y plane) with:
 *   - a Bubble3D to a fixed point in the middle, which keeps it inside a circle,
 *   - a PlaneContact3D, the floor, which it cannot go through,
 *   - a contact with every other marble (a contact group on the subset "marbles"),
 *     so that they bounce off each other.
 * Gravity pulls them down and air friction slowly calms them.
 *
 * Mouse: click to blow the marbles away from the mouse.
 * Keys: G turns gravity upside down.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, with the model's y axis pointing
 * UP (the drawing flips it). Gravity's direction is the "up" direction: masses
 * fall the opposite way.
 */

import tactus.*;

PhysicalModel mdl;
int nMarbles = 30;
float marbleRadius = 12;
float bowlRadius = 180;
float floorY = -120;     // the floor, in model coordinates (y up, 0 in the middle)
float up = 1;            // 1: gravity pulls down the screen, -1: up

void setup() {
  size(600, 600);
  frameRate(60);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0.0004);                      // per step squared: 400 pixels/s^2 at 1000 steps/s
  mdl.setGravityDirection(new Vect3D(0, 1, 0)); // "up" is +y, so marbles fall toward -y
  mdl.setFriction(0.0002);

  mdl.addGround3D("center", new Vect3D(0, 0, 0));
  mdl.createMatSubset("marbles");
  for (int i = 0; i < nMarbles; i++) {
    String name = "marble" + i;
    // Start on a loose grid, 6 per row, so that no two marbles overlap
    float x = (i % 6 - 2.5) * 2.6 * marbleRadius + random(-3, 3);
    float y = 100 - (i / 6) * 2.6 * marbleRadius;
    mdl.addMass2DPlane(name, 1.0, new Vect3D(x, y, 0), new Vect3D());
    mdl.addMatToSubset(name, "marbles");

    // name, radius, stiffness, damping, the mass kept inside, the centre
    mdl.addBubble3D("bowl" + i, bowlRadius - marbleRadius, 0.05, 0.01, name, "center");
    // name, offset, stiffness, damping, axis (0 = x, 1 = y, 2 = z), plane position, mass
    mdl.addPlaneContact("floor" + i, marbleRadius, 0.05, 0.01, 1, floorY, name);
  }
  // Every pair of marbles bounces like a Contact3D. A contact group finds the close pairs
  // itself, instead of one addContact3D per pair (435 links for 30 marbles, and 19,900 for
  // the paper's 200): same forces, much less work. The one-link-per-pair version would be:
  //   for (int i = 0; i < nMarbles; i++)
  //     for (int j = i + 1; j < nMarbles; j++)
  //       mdl.addContact3D("touch" + i + "_" + j, 2 * marbleRadius, 0.05, 0.005, "marble" + i, "marble" + j);
  mdl.addContactGroup("marbles", 2 * marbleRadius, 0.05, 0.005);
  mdl.init();
}

void draw() {
  mdl.draw_physics();

  background(245);
  translate(width / 2, height / 2);
  scale(1, -1);   // model y points up

  noFill();
  stroke(120);
  strokeWeight(2);
  ellipse(0, 0, 2 * bowlRadius, 2 * bowlRadius);
  float half = sqrt(bowlRadius * bowlRadius - floorY * floorY);
  line(-half, floorY, half, floorY);

  noStroke();
  for (int i = 0; i < nMarbles; i++) {
    String name = "marble" + i;
    PVector p = mdl.getMatPVector(name);
    Vect3D v = mdl.getMatVelocity(name);              // units (pixels) per second
    float speed = constrain((float) v.norm() / 400, 0, 1);
    fill(lerpColor(color(40, 90, 200), color(230, 60, 40), speed));
    ellipse(p.x, p.y, 2 * marbleRadius, 2 * marbleRadius);
  }

  scale(1, -1);
  fill(30);
  textSize(14);
  text("click: blow the marbles away    G: flip gravity", -width / 2 + 16, -height / 2 + 24);
  text(String.format("%d marbles, %d interactions + a contact group", mdl.getNumberOfMats() - 1, mdl.getNumberOfLinks()),
    -width / 2 + 16, height / 2 - 16);
}

void mousePressed() {
  float mx = mouseX - width / 2;
  float my = height / 2 - mouseY;
  for (int i = 0; i < nMarbles; i++) {
    String name = "marble" + i;
    PVector p = mdl.getMatPVector(name);
    float dx = p.x - mx;
    float dy = p.y - my;
    float d = max(sqrt(dx * dx + dy * dy), marbleRadius);
    if (d < 150) {
      // A one-step force changes the velocity by F / m pixels per step.
      float push = 0.8 * (1 - d / 150);
      mdl.triggerForceImpulse(name, push * dx / d, push * dy / d, 0);
    }
  }
}

void keyPressed() {
  if (key == 'g' || key == 'G') {
    up = -up;
    mdl.setGravityDirection(new Vect3D(0, up, 0));
  }
}
