/*
 * PluckedStringAudio: a string of 100 masses stepped once per audio sample, heard through Minim.
 * The string is a PhyUGen subclass built in its constructor, the paper's way; it plucks itself every
 * two seconds, click to pluck it where you click, and the arrow keys retune it while it sounds.
 *
 * Keys: UP / DOWN stiffness (pitch), LEFT / RIGHT damping, W starts / stops recording to a WAV file.
 */

import ddf.minim.*;
import tactus.*;
import tactus.audio.*;

Minim minim;
AudioOutput out;
AudioRecorder recorder;
StringUGen str;

int nMasses = 100;
float stiffness = 0.2;     // per step squared: the fundamental is near 98 Hz at 44.1 kHz
float damping = 0.0002;    // per step
int lastPluck = -10000;

class StringUGen extends PhyUGen {
  StringUGen() {
    super(44100);                              // mdl = new PhysicalModel(44100)
    mdl.addGround3D("left", new Vect3D(0, 0, 0));
    for (int i = 1; i <= nMasses; i++) {
      mdl.addMass2DPlane("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
    }
    mdl.addGround3D("right", new Vect3D(nMasses + 1, 0, 0));
    mdl.createLinkSubset("springs");
    for (int i = 0; i <= nMasses; i++) {
      String a = i == 0 ? "left" : "m" + i;
      String b = i == nMasses ? "right" : "m" + (i + 1);
      mdl.addSpringDamper3D("s" + i, 0, stiffness, damping, a, b);
      mdl.addLinkToSubset("s" + i, "springs");
    }
    mdl.init();
    listenToMass("m30", SteppedModel.Y, 1.2, -0.3);
    listenToMass("m71", SteppedModel.Y, 1.2, 0.3);
    setDcBlocker(0.995);                        // keeps the low fundamental (corner about 35 Hz)
  }
}

void setup() {
  size(800, 360);
  minim = new Minim(this);
  str = new StringUGen();
  out = LineOut.open(minim);                   // Minim's line out; works with no sound card too
  str.patch(out);
}

void pluck(int mass, float strength) {
  // queued: the audio thread applies it between two samples
  str.getModel().triggerForceImpulse("m" + mass, 0, strength, 0);
}

void draw() {
  if (millis() - lastPluck > 2000) {          // plays on its own
    lastPluck = millis();
    pluck(20 + (int) random(60), 0.06);
  }
  background(18, 22, 30);
  ModelSnapshot s = str.getModel().getSnapshot();
  float sx = width / (float) (nMasses + 1);
  stroke(240, 200, 110);
  strokeWeight(2);
  noFill();
  beginShape();
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    vertex((float) s.x(i) * sx, height / 2 + (float) s.y(i) * 150);
  }
  endShape();
  fill(230);
  noStroke();
  text("stiffness " + nf(stiffness, 1, 3) + " (UP/DOWN)   damping " + nf(damping, 1, 5) + " (LEFT/RIGHT)", 12, 20);
  text("click to pluck, W to " + (recorder != null && recorder.isRecording() ? "stop recording" : "record to string.wav"), 12, 38);
}

void mousePressed() {
  int m = constrain(round(mouseX / (width / (float) (nMasses + 1))), 1, nMasses);
  pluck(m, 0.06);
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    stiffness = constrain(stiffness * (keyCode == UP ? 1.1 : 1 / 1.1), 0.02, 0.9);
    str.getModel().changeStiffnessParamOfSubset(stiffness, "springs");
  } else if (keyCode == LEFT || keyCode == RIGHT) {
    damping = constrain(damping * (keyCode == RIGHT ? 1.5 : 1 / 1.5), 0.00001, 0.01);
    str.getModel().changeDampingParamOfSubset(damping, "springs");
  } else if (key == 'w' || key == 'W') {
    toggleRecording("string.wav");
  }
}

void toggleRecording(String file) {
  if (recorder == null) {
    recorder = minim.createRecorder(out, file);
  }
  if (recorder.isRecording()) {
    recorder.endRecord();
    try {
      recorder.save();
      println("saved " + sketchPath(file));
    } catch (RuntimeException e) {
      println("could not save " + file + ": " + e.getMessage());
    }
    recorder = null;
  } else {
    recorder.beginRecord();
  }
}
