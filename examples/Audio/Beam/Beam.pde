/*
 * Beam: a cantilever beam, 40 cells long and 2 x 2 masses thick, clamped at its left end and heard at its free
 * end. Springs along the edges and across the faces and diagonals make it stiff in bending; its partials are
 * inharmonic, like a bar's. It knocks itself every two seconds; click to knock it, and soften or stiffen it as it rings.
 *
 * Keys: UP / DOWN stiffness, LEFT / RIGHT damping, W starts / stops recording to a WAV file.
 */

import ddf.minim.*;
import tactus.*;
import tactus.audio.*;

Minim minim;
AudioOutput out;
AudioRecorder recorder;
PhysicalModel beam;
PhyUGen sound;

int len = 40;              // cells along x
float stiffness = 0.08;    // every spring, per step squared
float damping = 0.00003;   // every spring, per step
int lastKnock = -10000;
int springs = 0;

String m(int i, int j, int k) {
  return "b" + i + "_" + j + "_" + k;
}

void link(String a, String b) {
  String nameOf = "s" + springs++;
  Vect3D pa = beam.getMatPosition(a), pb = beam.getMatPosition(b);
  double rest = Math.sqrt(sq((float) (pa.x - pb.x)) + sq((float) (pa.y - pb.y)) + sq((float) (pa.z - pb.z)));
  beam.addSpringDamper3D(nameOf, rest, stiffness, damping, a, b);
  beam.addLinkToSubset(nameOf, "beam");
}

void setup() {
  size(900, 360);
  minim = new Minim(this);
  beam = new PhysicalModel(44100, 60);
  beam.createLinkSubset("beam");
  for (int i = 0; i <= len; i++) {
    for (int j = 0; j < 2; j++) {
      for (int k = 0; k < 2; k++) {
        Vect3D p = new Vect3D(i, j, k);
        if (i == 0) {
          beam.addGround3D(m(i, j, k), p);         // the clamped end
        } else {
          beam.addMass3D(m(i, j, k), 1, p, new Vect3D());
        }
      }
    }
  }
  for (int i = 0; i <= len; i++) {
    // across the cross-section: its four edges and two diagonals
    link(m(i, 0, 0), m(i, 1, 0));
    link(m(i, 0, 1), m(i, 1, 1));
    link(m(i, 0, 0), m(i, 0, 1));
    link(m(i, 1, 0), m(i, 1, 1));
    link(m(i, 0, 0), m(i, 1, 1));
    link(m(i, 1, 0), m(i, 0, 1));
    if (i < len) {
      // along the beam: straight to the next section, and diagonally across each side face
      for (int j = 0; j < 2; j++) {
        for (int k = 0; k < 2; k++) {
          link(m(i, j, k), m(i + 1, j, k));
          link(m(i, j, k), m(i + 1, 1 - j, k));
          link(m(i, j, k), m(i + 1, j, 1 - k));
        }
      }
    }
  }
  beam.init();

  sound = new PhyUGen(beam);
  sound.listenToMass(m(len, 0, 0), SteppedModel.Y, 4, -0.2);
  sound.listenToMass(m(len / 2, 1, 1), SteppedModel.Z, 4, 0.2);
  out = LineOut.open(minim);
  sound.patch(out);
}

void knock(int i, float force) {
  beam.triggerForceImpulse(m(i, 0, 0), 0, force, force * 0.6);   // queued for the audio thread
}

void draw() {
  if (millis() - lastKnock > 2000) {
    lastKnock = millis();
    knock(len - (int) random(len / 2), 0.05);
  }
  background(20, 22, 28);
  ModelSnapshot s = beam.getSnapshot();
  float sx = (width - 60) / (float) len;
  stroke(150, 190, 240);
  strokeWeight(1.5);
  for (int l = 0; l < s.getNumberOfLinks(); l++) {
    int a = s.getLinkMat1Idx(l), b = s.getLinkMat2Idx(l);
    line(30 + (float) s.x(a) * sx, height / 2 + (float) (s.y(a) - 0.5) * sx * 40 / 20 + (float) s.z(a) * 6,
         30 + (float) s.x(b) * sx, height / 2 + (float) (s.y(b) - 0.5) * sx * 40 / 20 + (float) s.z(b) * 6);
  }
  fill(230);
  noStroke();
  text("stiffness " + nf(stiffness, 1, 3) + " (UP/DOWN)   damping " + nf(damping, 1, 6) + " (LEFT/RIGHT)   click to knock, W to "
      + (recorder != null && recorder.isRecording() ? "stop recording" : "record beam.wav"), 12, 22);
}

void mousePressed() {
  int i = constrain(round((mouseX - 30) / ((width - 60) / (float) len)), 1, len);
  knock(i, 0.05);
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    stiffness = constrain(stiffness * (keyCode == UP ? 1.1 : 1 / 1.1), 0.005, 0.2);
    beam.changeStiffnessParamOfSubset(stiffness, "beam");
  } else if (keyCode == LEFT || keyCode == RIGHT) {
    damping = constrain(damping * (keyCode == RIGHT ? 2 : 0.5), 0.000001, 0.01);
    beam.changeDampingParamOfSubset(damping, "beam");
  } else if (key == 'w' || key == 'W') {
    if (recorder == null) {
      recorder = minim.createRecorder(out, "beam.wav");
    }
    if (recorder.isRecording()) {
      recorder.endRecord();
      try {
        recorder.save();
        println("saved " + sketchPath("beam.wav"));
      } catch (RuntimeException e) {
        println("could not save beam.wav: " + e.getMessage());
      }
      recorder = null;
    } else {
      recorder.beginRecord();
    }
  }
}
