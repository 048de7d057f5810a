/*
 * ExportToFaust: a 1-D string of 60 masses plays through Minim (it strikes itself every 1.5 seconds; click to
 * strike it where you click). Press E to write the model, as it is now, as a Faust program (string.dsp in the
 * sketch folder), with the PhyUGen's listening point as its output, a force input where the hammer hits and a
 * stiffness slider; the console prints the commands that turn it into a JACK program, a plugin or a web page.
 *
 * Keys: UP / DOWN stiffness (pitch), E exports string.dsp.
 */

import ddf.minim.*;
import tactus.*;
import tactus.audio.*;
import tactus.export.*;

Minim minim;
AudioOutput out;
PhysicalModel mdl;
PhyUGen sound;

int nMasses = 60;
float stiffness = 0.3;      // per step squared
float damping = 0.0003;     // per step
int strikeAt = 12;          // the mass the hammer hits
int lastStrike = -10000;
String status = "E exports string.dsp";

void setup() {
  size(800, 360);
  mdl = new PhysicalModel(44100, 60);
  mdl.addGround1D("left", new Vect3D(0, 0, 0));
  for (int i = 1; i <= nMasses; i++) {
    mdl.addMass1D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
  }
  mdl.addGround1D("right", new Vect3D(nMasses + 1, 0, 0));
  mdl.createLinkSubset("string");
  for (int i = 0; i <= nMasses; i++) {
    String a = i == 0 ? "left" : "m" + i;
    String b = i == nMasses ? "right" : "m" + (i + 1);
    mdl.addSpringDamper1D("s" + i, 0, stiffness, damping, a, b);
    mdl.addLinkToSubset("s" + i, "string");
  }
  mdl.init();
  minim = new Minim(this);
  sound = new PhyUGen(mdl);
  sound.listenToMass("m45", SteppedModel.Z, 0.5, 0);
  out = LineOut.open(minim);
  sound.patch(out);
}

void strike(int mass, float force) {
  mdl.triggerForceImpulse("m" + mass, 0, 0, force);   // queued for the audio thread
}

void draw() {
  if (millis() - lastStrike > 1500) {
    lastStrike = millis();
    strike(strikeAt, 0.5);
  }
  background(20, 24, 32);
  ModelSnapshot s = mdl.getSnapshot();
  float sx = width / (float) (nMasses + 1);
  stroke(120, 210, 240);
  strokeWeight(2);
  noFill();
  beginShape();
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    vertex((float) s.x(i) * sx, height / 2 - (float) s.z(i) * 300);
  }
  endShape();
  noStroke();
  fill(230);
  text("stiffness " + nf(stiffness, 1, 3) + " (UP/DOWN)   click to strike   " + status, 12, 20);
}

void mousePressed() {
  int mass = constrain(round(mouseX / (width / (float) (nMasses + 1))), 1, nMasses);
  strike(mass, 0.5);
}

void keyPressed() {
  if (keyCode == UP || keyCode == DOWN) {
    stiffness = constrain(stiffness * (keyCode == UP ? 1.1 : 1 / 1.1), 0.02, 0.9);
    mdl.changeStiffnessParamOfSubset(stiffness, "string");
  } else if (key == 'e' || key == 'E') {
    exportString();
  }
}

void exportString() {
  FaustExportOptions options = new FaustExportOptions().name("string");
  for (ListeningPoint p : sound.listeningPoints()) {          // the PhyUGen's listening points become outputs
    if (p.kind() == ListeningPoint.Kind.MASS_DISPLACEMENT) {
      options.listen(p.element(), p.axis(), p.gain());
    }
  }
  options.forceInput("m" + strikeAt, SteppedModel.Z);          // input 1: a force on the struck mass
  options.slider("stiffness", FaustExportOptions.STIFFNESS, "string");
  try {
    File dsp = FaustExporter.write(mdl, options, new File(sketchPath("string.dsp")));
    status = "wrote " + dsp.getName();
    println("Wrote " + dsp.getAbsolutePath() + " (run it at " + mdl.getSimRate() + " Hz). Turn it into:");
    println("  a JACK program:   faust2jack string.dsp");
    println("  an LV2 plugin:    faust2lv2 string.dsp");
    println("  a web page:       faust2wasm string.dsp");
    println("  C++ to read:      faust -double string.dsp -o string.cpp");
  } catch (IOException e) {
    status = "could not write string.dsp";
    println("could not write string.dsp: " + e.getMessage());
  }
}
