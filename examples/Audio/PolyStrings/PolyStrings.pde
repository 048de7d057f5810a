/*
 * PolyStrings: a polyphonic instrument. Six voices of one 40-mass string are built side by side in one model
 * (a VoiceBank) and heard through one PhyUGen. Each note takes the next voice in turn, tunes its springs to the
 * note and strikes it; the sketch plays an arpeggio on its own.
 *
 * Keys: 1-8 play the notes of an A minor scale (A3 to A4), SPACE starts / stops the arpeggio,
 * W starts / stops recording to a WAV file.
 */

import ddf.minim.*;
import tactus.*;
import tactus.audio.*;

Minim minim;
AudioOutput out;
AudioRecorder recorder;
PhysicalModel model;
VoiceBank bank;
PhyUGen voices;

int nMasses = 40;
int nVoices = 6;
float[] scale = {220.00, 246.94, 261.63, 293.66, 329.63, 349.23, 392.00, 440.00};   // Hz
String[] names = {"A3", "B3", "C4", "D4", "E4", "F4", "G4", "A4"};
int[] noteOfVoice;        // the note each voice last played, for the labels
int[] firstMass;          // index of each voice's first mass in the model (and its snapshots)
boolean arpeggio = true;
int nextNote = 0;
int lastNote = -10000;

void setup() {
  size(800, 450);
  minim = new Minim(this);
  model = new PhysicalModel(44100);
  // one voice: a string of Mass1D (moving along z) between two fixed points, its springs in a subset
  bank = new VoiceBank(model, nVoices, (m, prefix, voice) -> {
    m.addGround1D(prefix + "left", new Vect3D(0, 0, 0));
    for (int i = 1; i <= nMasses; i++) {
      m.addMass1D(prefix + "m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
    }
    m.addGround1D(prefix + "right", new Vect3D(nMasses + 1, 0, 0));
    m.createLinkSubset(prefix + "springs");
    for (int i = 0; i <= nMasses; i++) {
      String a = i == 0 ? "left" : "m" + i;
      String b = i == nMasses ? "right" : "m" + (i + 1);
      m.addSpringDamper1D(prefix + "s" + i, 0, stiffnessFor(220), 0.0003, prefix + a, prefix + b);
      m.addLinkToSubset(prefix + "s" + i, prefix + "springs");
    }
  });
  model.init();
  voices = new PhyUGen(model);
  bank.listenToMass(voices, "m13", SteppedModel.Z, 0.5, 0.7);   // each voice at its own place in the stereo field
  voices.setDcBlocker(0.995);
  out = LineOut.open(minim);
  voices.patch(out);
  noteOfVoice = new int[nVoices];
  firstMass = new int[nVoices];
  for (int v = 0; v < nVoices; v++) {
    noteOfVoice[v] = -1;
    firstMass[v] = model.getMatIndex(bank.name(v, "m1"));
  }
}

/** The spring stiffness (per step squared) whose string's first mode rings at f Hz. */
double stiffnessFor(double f) {
  double w = 2 * Math.PI * f / 44100;                      // radians per step
  double s = Math.sin(w / 2) / Math.sin(Math.PI / (2 * (nMasses + 1)));
  return s * s;
}

void play(int note) {
  int v = bank.nextVoice();
  model.changeStiffnessParamOfSubset(stiffnessFor(scale[note]), bank.name(v, "springs"));
  model.triggerForceImpulse(bank.name(v, "m7"), 0, 0, 0.08);  // queued: applied between two samples
  noteOfVoice[v] = note;
}

void draw() {
  if (arpeggio && millis() - lastNote > 300) {
    lastNote = millis();
    int[] pattern = {0, 2, 4, 7, 4, 2};
    play(pattern[nextNote++ % pattern.length]);
  }
  background(18, 22, 30);
  ModelSnapshot s = model.getSnapshot();
  float row = (height - 60) / (float) nVoices;
  float sx = (width - 80) / (float) (nMasses + 1);
  noFill();
  strokeWeight(2);
  for (int v = 0; v < nVoices; v++) {
    float y0 = 60 + row * (v + 0.5);
    stroke(120 + 20 * v, 200 - 15 * v, 110 + 25 * v);
    beginShape();
    vertex(70, y0);
    for (int i = 0; i < nMasses; i++) {
      vertex(70 + (i + 1) * sx, y0 + (float) s.z(firstMass[v] + i) * 150);
    }
    vertex(70 + (nMasses + 1) * sx, y0);
    endShape();
    fill(230);
    text("voice " + v + (noteOfVoice[v] >= 0 ? "  " + names[noteOfVoice[v]] : ""), 8, y0 + 4);
    noFill();
  }
  fill(230);
  text("keys 1-8: notes A3..A4   SPACE: arpeggio " + (arpeggio ? "on" : "off")
      + "   W: " + (recorder != null && recorder.isRecording() ? "stop recording" : "record to voices.wav"), 12, 20);
  text(nVoices + " voices of a " + nMasses + "-mass string in one model, one PhyUGen", 12, 38);
}

void keyPressed() {
  if (key >= '1' && key <= '8') {
    play(key - '1');
  } else if (key == ' ') {
    arpeggio = !arpeggio;
  } else if (key == 'w' || key == 'W') {
    toggleRecording("voices.wav");
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
