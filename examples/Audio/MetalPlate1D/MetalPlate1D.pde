/*
 * MetalPlate1D: a square plate of 24 x 24 masses that move along z only, each held by a weak internal spring
 * (Osc1D) and joined to its neighbours by 1D spring-dampers, struck like a gong. It strikes itself at a random
 * point every 1.5 seconds; click the plate to strike it there, and change its stiffness and damping as it rings.
 *
 * Keys: UP / DOWN stiffness, LEFT / RIGHT damping, W starts / stops recording to a WAV file.
 */

import ddf.minim.*;
import tactus.*;
import tactus.audio.*;

Minim minim;
AudioOutput out;
AudioRecorder recorder;
PhysicalModel plate;
PhyUGen sound;

int n = 24;                 // masses per side
float stiffness = 0.15;     // neighbour springs, per step squared
float damping = 0.00002;    // neighbour dampers, per step
int lastStrike = -10000;

String name(int i, int j) {
  return "p" + i + "_" + j;
}

void setup() {
  size(640, 640);
  minim = new Minim(this);
  plate = new PhysicalModel(44100, 60);
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      // an oscillator along z: mass 1, a weak spring to its rest point, no damping of its own
      plate.addOsc1D(name(i, j), 1, 0.0005, 0, new Vect3D(i, j, 0), new Vect3D());
    }
  }
  plate.createLinkSubset("plate");
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      if (i + 1 < n) {
        plate.addSpringDamper1D("x" + i + "_" + j, 0, stiffness, damping, name(i, j), name(i + 1, j));
        plate.addLinkToSubset("x" + i + "_" + j, "plate");
      }
      if (j + 1 < n) {
        plate.addSpringDamper1D("y" + i + "_" + j, 0, stiffness, damping, name(i, j), name(i, j + 1));
        plate.addLinkToSubset("y" + i + "_" + j, "plate");
      }
    }
  }
  plate.init();

  sound = new PhyUGen(plate);                  // the direct way: a model built elsewhere
  sound.listenToMass(name(3, 5), SteppedModel.Z, 3, -0.4);
  sound.listenToMass(name(n - 6, n - 3), SteppedModel.Z, 3, 0.4);
  out = LineOut.open(minim);
  sound.patch(out);
}

void strike(int i, int j, float force) {
  plate.triggerForceImpulse(name(i, j), 0, 0, force);   // queued for the audio thread
}

void draw() {
  if (millis() - lastStrike > 1500) {
    lastStrike = millis();
    strike((int) random(n), (int) random(n), 0.3);
  }
  background(16);
  ModelSnapshot s = plate.getSnapshot();
  float cell = (width - 40) / (float) n;
  noStroke();
  for (int k = 0; k < s.getNumberOfMats(); k++) {
    float z = (float) s.z(k);
    fill(128 + constrain(z * 4000, -127, 127), 140, 128 - constrain(z * 4000, -127, 127));
    rect(20 + (float) s.x(k) * cell, 40 + (float) s.y(k) * cell * 0.94, cell - 2, cell * 0.94 - 2);
  }
  fill(230);
  text("stiffness " + nf(stiffness, 1, 3) + " (UP/DOWN)   damping " + nf(damping, 1, 6) + " (LEFT/RIGHT)   click to strike, W to "
      + (recorder != null && recorder.isRecording() ? "stop recording" : "record plate.wav"), 12, 22);
}

void mousePressed() {
  float cell = (width - 40) / (float) n;
  int i = constrain((int) ((mouseX - 20) / cell), 0, n - 1);
  int j = constrain((int) ((mouseY - 40) / (cell * 0.94)), 0, n - 1);
  strike(i, j, 0.3);
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    stiffness = constrain(stiffness * (keyCode == UP ? 1.1 : 1 / 1.1), 0.01, 0.45);
    plate.changeStiffnessParamOfSubset(stiffness, "plate");
  } else if (keyCode == LEFT || keyCode == RIGHT) {
    damping = constrain(damping * (keyCode == RIGHT ? 2 : 0.5), 0.000001, 0.01);
    plate.changeDampingParamOfSubset(damping, "plate");
  } else if (key == 'w' || key == 'W') {
    if (recorder == null) {
      recorder = minim.createRecorder(out, "plate.wav");
    }
    if (recorder.isRecording()) {
      recorder.endRecord();
      try {
        recorder.save();
        println("saved " + sketchPath("plate.wav"));
      } catch (RuntimeException e) {
        println("could not save plate.wav: " + e.getMessage());
      }
      recorder = null;
    } else {
      recorder.beginRecord();
    }
  }
}
