/*
 * Lesson05_HearTheString: step 5 of the classroom lesson (docs/classroom.md).
 *
 * The string of step 4, run 44.1 times faster: 44100 steps per second, one step per audio sample.
 * A PhyUGen (a Minim sound generator) now steps the model on the audio thread, and a listening
 * point turns the up-and-down motion of one mass into sound. The springs are the same, so the
 * wave that took 0.4 s to go and come back now does it 110 times a second: you hear about 110 Hz.
 * draw() no longer steps the model; it draws the snapshot that the audio thread publishes.
 *
 * Mouse: click to pluck where you click.  Keys: UP / DOWN stiffer or softer springs (pitch).
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y up (the drawing flips it).
 */

import tactus.*;
import tactus.audio.*;
import ddf.minim.*;

PhysicalModel mdl;
PhyUGen string;
Minim minim;
AudioOutput out;
int masses = 30;
float K = 0.05;          // the same springs as in step 4, per step²
float Z = 0.0001;        // less damping per step: there are 44 times more steps per second
float left, right, y, spacing;
int lastPluck = -10000;

void setup() {
  size(600, 400);
  frameRate(60);
  left = 50;
  right = width - 50;
  y = height / 2;
  spacing = (right - left) / (masses + 1);

  mdl = new PhysicalModel(44100, 60);   // one step per audio sample
  mdl.setFriction(0.00001);
  buildString();
  mdl.init();

  string = new PhyUGen(mdl);                       // the audio thread steps the model from now on
  string.listenToMass("m3", SteppedModel.Y, 0.02, 0);   // mass 3, up and down, gain, pan (centre)
  minim = new Minim(this);
  out = LineOut.open(minim);                       // the sound card (a silent output if there is none)
  string.patch(out);
  pluck(8, 40);
}

void buildString() {
  mdl.addGround3D("g0", new Vect3D(left, y, 0));
  for (int i = 1; i <= masses; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(left + i * spacing, y, 0), new Vect3D());
  }
  mdl.addGround3D("g" + (masses + 1), new Vect3D(right, y, 0));
  mdl.createLinkSubset("springs");
  for (int i = 0; i <= masses; i++) {
    mdl.addSpringDamper3D("s" + i, spacing / 2, K, Z, name(i), name(i + 1));
    mdl.addLinkToSubset("s" + i, "springs");
  }
}

void draw() {
  if (millis() - lastPluck > 2000) {   // plays on its own every 2 s
    pluck(int(random(3, masses - 2)), 40);
  }
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the audio thread

  background(18, 22, 30);
  pushMatrix();
  translate(0, height);
  scale(1, -1);
  stroke(240, 200, 110);
  strokeWeight(2);
  noFill();
  beginShape();
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    vertex((float) s.x(i), (float) s.y(i));
  }
  endShape();
  popMatrix();

  fill(230);
  textSize(14);
  text("Step 5: hear the string (44100 steps per second).   Click: pluck   UP/DOWN: pitch", 12, 22);
  text(String.format("K %.3f: about %.0f Hz", K, 44100 / (2.0 * (masses + 1)) * sqrt(K / 2)), 12, 42);
}

String name(int i) {
  return i == 0 || i == masses + 1 ? "g" + i : "m" + i;
}

// As in step 4. The audio thread owns the model now: these calls are queued, and it makes them
// between two samples.
void pluck(int at, float h) {
  lastPluck = millis();
  for (int i = 1; i <= masses; i++) {
    float lift = i <= at ? h * i / at : h * (masses + 1 - i) / (masses + 1 - at);
    mdl.setMatPosition("m" + i, new Vect3D(left + i * spacing, y + lift, 0));
  }
}

void mousePressed() {
  pluck(constrain(round((mouseX - left) / spacing), 1, masses), 40);
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    K = constrain(K * (keyCode == UP ? 1.25 : 0.8), 0.005, 0.8);
    mdl.changeStiffnessParamOfSubset(K, "springs");
  }
}
