// Validates glTF files with the Khronos glTF-Validator: prints each file's error and warning counts and every
// issue's code, path and message; exits 1 if any file has an error (warnings are listed, not fatal), 77 (the
// test's "skipped") when the validator is not installed (bash tools/setup.sh installs it).
// usage: node tools/gltf-validate/validate.mjs FILE...
import fs from 'node:fs/promises';
import path from 'node:path';

let validator;
try {
    validator = await import('gltf-validator');
} catch {
    console.log('gltf-validate: the gltf-validator package is missing (npm install in tools/gltf-validate; ' +
                'bash tools/setup.sh does it); skipped');
    process.exit(77);
}

const files = process.argv.slice(2);
if (files.length === 0) {
    console.error('gltf-validate: usage: node validate.mjs FILE...');
    process.exit(2);
}
let failed = 0;
for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(await fs.readFile(file)), {
        uri: file,
        maxIssues: 100,
        externalResourceFunction: async (uri) =>
            new Uint8Array(await fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))),
    });
    const { numErrors, numWarnings, messages } = report.issues;
    console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings`);
    for (const issue of messages.filter((m) => m.severity <= 1)) {
        console.log(`  ${issue.severity === 0 ? 'error' : 'warning'} ${issue.code} at ${issue.pointer}: ${issue.message}`);
    }
    failed += numErrors > 0;
}
console.log(`gltf-validate: ${files.length - failed} passed, ${failed} failed`);
process.exit(failed > 0 ? 1 : 0);
