// Validates glTF files with the Khronos glTF-Validator (npm "gltf-validator", installed by
// tools/install-gltf-validator.sh). Prints each file's error/warning counts and its messages;
// exits 1 when any file has an error, 2 for a usage problem, 77 when the validator is not
// installed (the CTest test treats 77 as "skipped").
//
//   node tools/validate_gltf.cjs VALIDATOR_DIR FILE.gltf|FILE.glb...
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, ...files] = process.argv.slice(2);
if (!validatorDir || files.length === 0) {
    console.error('usage: node validate_gltf.cjs VALIDATOR_DIR FILE...');
    process.exit(2);
}
let validator;
try {
    validator = require(path.join(validatorDir, 'node_modules', 'gltf-validator'));
} catch (e) {
    console.log(`gltf-validator is not installed in ${validatorDir} (run tools/install-gltf-validator.sh)`);
    process.exit(77);
}

(async () => {
    let failed = false;
    for (const file of files) {
        const folder = path.dirname(file);
        const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
            uri: path.basename(file),
            maxIssues: 100,
            externalResourceFunction: (uri) =>
                new Promise((resolve, reject) => {
                    fs.readFile(path.join(folder, decodeURIComponent(uri)), (err, data) =>
                        err ? reject(err.toString()) : resolve(new Uint8Array(data)));
                }),
        });
        const issues = report.issues;
        console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos`);
        for (const m of issues.messages)
            if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} at ${m.pointer}: ${m.message}`);
        if (issues.numErrors > 0) failed = true;
    }
    process.exit(failed ? 1 : 0);
})().catch((e) => {
    console.error(e.toString());
    process.exit(1);
});
