/*
 * Lesson06_PluckedString: step 6, the last of the classroom lesson (docs/classroom.md).
 *
 * The string of step 5, heard, and now touched: a plectrum (a HapticInput3D, the hand's place in the
 * model) touches every mass of the string through a contact (a Contact3D: a spring that pushes only
 * when the two are closer than a distance). A HapticSession moves the plectrum with the Haply's
 * handle 1000 times a second and sends the contacts' force back to the motors. With no Haply plugged
 * in, an emulated one is used and the mouse is the hand; until the mouse moves, the hand tours the
 * workspace on its own and plucks the string as it crosses it.
 *
 * Mouse (no Haply): move it across the string slowly to pluck.  Keys: SPACE plucks it for you.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y up (the drawing flips it).
 */

import tactus.*;
import tactus.audio.*;
import tactus.haptics.*;
import ddf.minim.*;

PhysicalModel mdl;
PhyUGen string;
Minim minim;
AudioOutput out;
HapticSession haptics;
int masses = 30;
float K = 0.05;
float Z = 0.0001;
float sphere = 15;       // the plectrum touches a mass closer than this, pixels
float left, right, y, spacing;
double[] force = new double[2];
int plectrum;            // the plectrum's index in the model's snapshot

void setup() {
  size(800, 450);
  frameRate(60);

  // The device first: the string goes where the handle can reach.
  haptics = HapticSession.open(this);   // a Haply, or the emulator with the mouse as the hand
  haptics.setModelYUp(true);            // this sketch's y points up
  double[] ws = new double[4];          // what the handle reaches, in pixels: xmin, xmax, ymin, ymax
  haptics.workspace(ws);
  left = (float) (ws[0] + 0.1 * (ws[1] - ws[0]));
  right = (float) (ws[1] - 0.1 * (ws[1] - ws[0]));
  y = (float) (ws[2] + ws[3]) / 2;
  spacing = (right - left) / (masses + 1);

  mdl = new PhysicalModel(44100, 60);
  mdl.setFriction(0.00001);
  buildString();
  // the plectrum: name, where it starts, smoothing (it follows the handle over 40 steps)
  mdl.addHapticInput3D("plectrum", haptics.home(), 40);
  for (int i = 1; i <= masses; i++) {
    // name, distance, K, Z, the two masses
    mdl.addContact3D("pick" + i, sphere, 0.01, 0.001, "plectrum", "m" + i);
  }
  mdl.init();
  plectrum = mdl.getMatIndex("plectrum");

  string = new PhyUGen(mdl);
  string.listenToMass("m3", SteppedModel.Y, 0.02, 0);
  minim = new Minim(this);
  out = LineOut.open(minim);
  string.patch(out);
  pluck(8, 30);

  // The haptic loop: the audio thread steps the model (AUDIO mode); the loop moves the plectrum
  // and sends the force back, 6 newtons per unit of model force.
  HapticLoop loop = haptics.attach(mdl, "plectrum");
  loop.setMode(HapticLoop.Mode.AUDIO);
  loop.setForceGain(6);
  loop.start();
}

void buildString() {
  mdl.addGround3D("g0", new Vect3D(left, y, 0));
  for (int i = 1; i <= masses; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(left + i * spacing, y, 0), new Vect3D());
  }
  mdl.addGround3D("g" + (masses + 1), new Vect3D(right, y, 0));
  for (int i = 0; i <= masses; i++) {
    mdl.addSpringDamper3D("s" + i, spacing / 2, K, Z, name(i), name(i + 1));
  }
}

void draw() {
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the audio thread

  background(18, 22, 30);
  pushMatrix();
  translate(0, height);
  scale(1, -1);
  stroke(240, 200, 110);
  strokeWeight(2);
  noFill();
  beginShape();
  for (int i = 0; i <= masses + 1; i++) {   // the string's points were added first: g0, m1 .. m30, g31
    vertex((float) s.x(i), (float) s.y(i));
  }
  endShape();
  float px = (float) s.x(plectrum);
  float py = (float) s.y(plectrum);
  noStroke();
  fill(230, 60, 60);
  ellipse(px, py, 2 * sphere, 2 * sphere);
  haptics.forceInModel(force);          // newtons, along the model's axes: 20 pixels per newton
  stroke(255, 230, 90);
  strokeWeight(3);
  line(px, py, px + 20 * (float) force[0], py + 20 * (float) force[1]);
  popMatrix();

  fill(230);
  textSize(14);
  text("Step 6: pluck the string with the plectrum (red), hear it and feel it.   SPACE: pluck", 12, 22);
  text(String.format("force on the hand %.2f N", Math.hypot(force[0], force[1])), 12, 42);
  haptics.drawStatus();                 // which Haply, or that the mouse is the hand
}

String name(int i) {
  return i == 0 || i == masses + 1 ? "g" + i : "m" + i;
}

void pluck(int at, float h) {
  for (int i = 1; i <= masses; i++) {
    float lift = i <= at ? h * i / at : h * (masses + 1 - i) / (masses + 1 - at);
    mdl.setMatPosition("m" + i, new Vect3D(left + i * spacing, y + lift, 0));
  }
}

void keyPressed() {
  if (key == ' ') {
    pluck(int(random(3, masses - 2)), 30);
  }
}
