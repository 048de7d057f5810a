/*
 * ForgivenLoops: written the way the paper's example sketches were (EnclosedMarbles, RollingPebbles, HapticBeam,
 * WobbleBeamMidi, BeamBender), with the mistakes the paper's engine silently ignored:
 * - loops over every module that include the module they link to, so one link joins a module to itself;
 * - MIDI controllers on "col", the name of the contacts, not of a subset;
 * - a subset that was never created ("stretchingFactor"), changed at every frame.
 * Tactus runs it as the original did, with one warning per kind of problem (ForgivenSketchesTest).
 * Keys: A and E turn the MIDI knobs, Z changes the subset that does not exist.
 */

import tactus.*;

PhysicalModel mdl;
ArrayList<MidiController> midiCtrls = new ArrayList<MidiController>();
int nbMass = 10;
float zoom = 60;

void setup() {
  size(480, 360);
  frameRate(60);

  mdl = new PhysicalModel(600, 60);
  mdl.setFriction(0.0005);

  mdl.addGround3D("gnd", new Vect3D(0, 0, 0));
  for (int i = 0; i < nbMass; i++) {
    mdl.addMass3D("mass"+i, 1, new Vect3D(1.6*cos(TWO_PI*i/nbMass), 1.6*sin(TWO_PI*i/nbMass), 0), new Vect3D(0, 0, 0));
  }
  mdl.addHapticInput3D("hapticMass", new Vect3D(0, 0, 0), 1);

  // every module stays within 2.5 of the ground "gnd": the loop includes "gnd" itself
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    mdl.addBubble3D("bub"+i, 2.5, 0.01, 0.01, "gnd", mdl.getMatNameAt(i));
  }
  // the avatar pushes every module: the loop includes the avatar itself
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    mdl.addContact3D("col", 0.6, 0.05, 0.01, "hapticMass", mdl.getMatNameAt(i));
  }
  for (int i = 0; i < nbMass; i++) {
    for (int j = 0; j < nbMass; j++) {
      if (i != j)
        mdl.addContact3D("cont"+i+"_"+j, 0.3, 0.02, 0.01, "mass"+j, "mass"+i);
    }
  }
  mdl.init();

  midiCtrls.add(MidiController.addMidiController(mdl, 4, 0.01, 0.1, "col", "stiffness"));
  midiCtrls.add(MidiController.addMidiController(mdl, 5, 0.0001, 0.01, "col", "damping"));
}

void draw() {
  mdl.setHapticPosition("hapticMass", new Vect3D(1.5*cos(frameCount*0.04), 1.5*sin(frameCount*0.03), 0));
  mdl.draw_physics();
  mdl.changeDampingParamOfSubset(0.001, "stretchingFactor");

  background(20);
  translate(width/2, height/2);
  noStroke();
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    PVector p = mdl.getMatPosAt(i).toPVector();
    if (mdl.getMatTypeAt(i) == matModuleType.HapticInput3D) fill(255, 80, 80);
    else if (mdl.getMatTypeAt(i) == matModuleType.Ground3D) fill(120);
    else fill(120, 200, 255);
    ellipse(p.x * zoom, p.y * zoom, 16, 16);
  }
}

void keyPressed() {
  if (key == 'a') {
    for (MidiController mc : midiCtrls) mc.changeParam(4, 100);
  }
  if (key == 'e') {
    for (MidiController mc : midiCtrls) mc.changeParam(5, 20);
  }
  if (key == 'z') {
    mdl.changeStiffnessParamOfSubset(0.2, "stretchingFactor");
  }
}
