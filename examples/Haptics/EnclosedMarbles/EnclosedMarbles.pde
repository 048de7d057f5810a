/*
 * EnclosedMarbles: stir two hundred marbles with the Haply.
 * The marbles fall onto a floor inside a round bubble and settle; push into them with the
 * avatar (red) and feel them roll, pile up and bounce against the walls. Keys 1, 2 and 3
 * trade the loop's rate for the number of marbles, as the paper did (600 marbles at 200 Hz).
 *
 * With no Haply plugged in, the sketch runs the board emulator and the mouse is your hand.
 *
 * Controls: 1 200 marbles at 1 kHz, 2 600 marbles at 200 Hz, 3 1000 marbles at 1 kHz,
 * G shake (gravity up for a moment), T print the loop's telemetry.
 * Each marble touches every other through one contact group (the engine finds the close
 * pairs), not one Contact3D per pair: the same forces for much less work, which is what
 * makes scene 3 possible. Units: ALGO_UNITS, 1 model unit = 1 pixel, the model's y axis
 * pointing UP (the drawing flips it), so that the floor's plane contact holds the marbles.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession haptics;

int nMarbles;
int rate;                 // steps per second of the haptic loop (and of the model)
float radius;             // marble radius, pixels
float avatarRadius = 16;
float bubbleRadius = 175;
float floorY;             // the floor, below the bubble's centre (model y points up)
float cx, cy;             // the bubble's centre
int[] marbleIndex;
int avatarIndex;
int shakeUntil;           // frame until which gravity points up
double[] force = new double[2];

void setup() {
  size(800, 600);
  frameRate(60);
  cx = width / 2;
  cy = height / 2;
  floorY = cy - 110;
  // A Haply if one is plugged in, otherwise the emulator with the mouse as the hand.
  haptics = HapticSession.open(this);
  haptics.setModelYUp(true);   // model y = height - pixel y
  scene(200, 1000, 7);
}

/** Builds a scene and (re)starts the haptic loop on it: the previous loop stops first. */
void scene(int n, int stepsPerSecond, float r) {
  nMarbles = n;
  rate = stepsPerSecond;
  radius = r;
  // Per-step parameters. Gravity and air friction are given per second and converted, so
  // the marbles fall alike at any rate; contacts keep the same per-step stiffness, so at
  // 200 Hz they are softer in real time (less sharp dynamics, as the paper says).
  float g = 400.0 / (rate * rate);         // 400 pixels per second squared
  PhysicalModel m = new PhysicalModel(rate, 60, paramSystem.ALGO_UNITS);
  m.setGravity(g);
  m.setGravityDirection(new Vect3D(0, 1, 0));   // "up" is +y: masses fall toward -y
  m.setFriction(0.3 / rate);
  m.addGround3D("centre", new Vect3D(cx, cy, 0));
  m.addHapticInput3D("avatar", haptics.home(), 10);
  m.createMatSubset("marbles");
  int perRow = (int) (1.6 * bubbleRadius / (2.2 * r));
  for (int i = 0; i < n; i++) {
    String name = "marble" + i;
    float x = cx + (i % perRow - (perRow - 1) / 2.0) * 2.2 * r + random(-0.5, 0.5);
    float y = floorY + r + (i / perRow) * 2.2 * r;
    m.addMass2DPlane(name, 1, new Vect3D(x, y, 0), new Vect3D());
    m.addMatToSubset(name, "marbles");
    // kept inside the bubble, above the floor, and pushed by the avatar
    m.addBubble3D("wall" + i, bubbleRadius - r, 0.05, 0.01, name, "centre");
    m.addPlaneContact("floor" + i, r, 0.05, 0.01, 1, floorY, name);
    m.addContact3D("touch" + i, r + avatarRadius, 0.05, 0.005, "avatar", name);
  }
  m.addContactGroup("marbles", 2 * r, 0.05, 0.005);
  m.init();
  marbleIndex = new int[n];
  for (int i = 0; i < n; i++) {
    marbleIndex[i] = m.getMatIndex("marble" + i);
  }
  avatarIndex = m.getMatIndex("avatar");
  mdl = m;
  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setRate(rate);
  loop.setForceGain(0.6);   // newtons per model force unit: a 10-pixel push into a marble is 0.3 N
  loop.start();
}

void draw() {
  if (frameCount == shakeUntil) {
    mdl.setGravityDirection(new Vect3D(0, 1, 0));
  }
  background(240, 238, 232);
  pushMatrix();
  translate(0, height);
  scale(1, -1);   // model y points up
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the haptic thread

  noFill();
  stroke(150);
  strokeWeight(2);
  ellipse(cx, cy, 2 * bubbleRadius, 2 * bubbleRadius);
  float half = sqrt(bubbleRadius * bubbleRadius - (floorY - cy) * (floorY - cy));
  line(cx - half, floorY, cx + half, floorY);

  noStroke();
  fill(40, 90, 200);
  for (int i = 0; i < nMarbles; i++) {
    int k = marbleIndex[i];
    ellipse((float) s.x(k), (float) s.y(k), 2 * radius, 2 * radius);
  }

  float ax = (float) s.x(avatarIndex);
  float ay = (float) s.y(avatarIndex);
  haptics.forceInModel(force);
  stroke(240, 150, 30);
  strokeWeight(3);
  line(ax, ay, ax + 40 * (float) force[0], ay + 40 * (float) force[1]);
  noStroke();
  fill(230, 60, 50, 200);
  ellipse(ax, ay, 2 * avatarRadius, 2 * avatarRadius);
  popMatrix();

  fill(30);
  textSize(14);
  text("Stir the marbles.   1: 200 at 1 kHz   2: 600 at 200 Hz   3: 1000 at 1 kHz   G: shake   T: telemetry", 12, 22);
  text(String.format("%d marbles at %d Hz   force %.2f N   %s", nMarbles, rate, Math.hypot(force[0], force[1]),
    haptics.telemetryLine()), 12, 42);
  haptics.drawStatus();   // which board, or that the mouse is your hand
}

void keyPressed() {
  if (key == '1') {
    scene(200, 1000, 7);
  } else if (key == '2') {
    scene(600, 200, 5);
  } else if (key == '3') {
    scene(1000, 1000, 4);
  } else if (key == 'g' || key == 'G') {
    mdl.setGravityDirection(new Vect3D(0, -1, 0));
    shakeUntil = frameCount + 20;
  } else if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
